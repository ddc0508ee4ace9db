using System;
using System.IO;
using System.IO.Compression;
using Rendering.Imaging;

namespace Rendering.Tests.Imaging;

public class PngRoundTripTests
{
  [Theory]
  [InlineData(1, 1)]
  [InlineData(7, 3)]
  [InlineData(3, 7)]
  [InlineData(2, 1)]
  [InlineData(1, 5)]
  [InlineData(641, 2)]
  [InlineData(640, 480)]
  public void RandomImageRoundTripsExactly(int width, int height)
  {
    Rgb8Image original = PngTestFiles.RandomImage(width, height, seed: width * 1000 + height);
    Rgb8Image decoded = TestDecode.Png(PngEncoder.Default.Encode(original));
    Assert.Equal(width, decoded.Width);
    Assert.Equal(height, decoded.Height);
    Assert.Equal(original.Data, decoded.Data);
  }

  [Theory]
  [InlineData(0)]
  [InlineData(1)]
  [InlineData(2)]
  [InlineData(3)]
  [InlineData(4)]
  public void EveryForcedFilterRoundTrips(int filter)
  {
    PngEncoder encoder = new() { ForcedFilter = filter };
    foreach (Rgb8Image original in new[] { PngTestFiles.RandomImage(33, 17, filter), PngTestFiles.RenderLikeImage(40, 30, filter) })
    {
      byte[] png = encoder.Encode(original);
      Assert.All(FilterBytes(png, original.Width * 3), b => Assert.Equal(filter, b));
      Assert.Equal(original.Data, TestDecode.Png(png).Data);
    }
  }

  [Fact]
  public void AdaptiveEncoderUsesSeveralFiltersOnRenderLikeImage()
  {
    byte[] png = PngEncoder.Default.Encode(PngTestFiles.RenderLikeImage(64, 48, 1));
    Assert.True(new System.Collections.Generic.HashSet<byte>(FilterBytes(png, 64 * 3)).Count >= 2);
  }

  [Theory]
  [InlineData(CompressionLevel.Fastest)]
  [InlineData(CompressionLevel.Optimal)]
  [InlineData(CompressionLevel.SmallestSize)]
  [InlineData(CompressionLevel.NoCompression)]
  public void EveryCompressionLevelRoundTrips(CompressionLevel level)
  {
    Rgb8Image original = PngTestFiles.RenderLikeImage(100, 60, 7);
    Assert.Equal(original.Data, TestDecode.Png(new PngEncoder { CompressionLevel = level }.Encode(original)).Data);
  }

  [Fact]
  public void UnknownCompressionLevelIsRejected()
  {
    Assert.Throws<ArgumentOutOfRangeException>(() => new PngEncoder { CompressionLevel = (CompressionLevel)42 });
  }

  [Fact]
  public void RgbaRoundTripKeepsColorAndWritesColorType6()
  {
    byte[] rgba = new byte[5 * 3 * 4];
    new Random(5).NextBytes(rgba);
    using MemoryStream ms = new();
    PngEncoder.Default.EncodeRgba(rgba, 5, 3, ms);
    byte[] png = ms.ToArray();
    Assert.Equal(6, png[8 + 8 + 9]);

    Rgb8Image decoded = TestDecode.Png(png);
    for (int p = 0; p < 15; p++)
      Assert.Equal(rgba.AsSpan(4 * p, 3).ToArray(), decoded.Data.AsSpan(3 * p, 3).ToArray());
  }

  [Fact]
  public void EncodedFileHasExpectedChunkLayout()
  {
    byte[] png = PngEncoder.Default.Encode(new Rgb8Image(7, 3));
    Assert.Equal(PngTestFiles.Signature, png[..8]);
    var chunks = PngTestFiles.Chunks(png);
    Assert.Equal("IHDR", chunks[0].Type);
    Assert.Equal(13, chunks[0].Length);
    Assert.Equal(new byte[] { 0, 0, 0, 7, 0, 0, 0, 3, 8, 2, 0, 0, 0 }, png[16..29]);
    Assert.Equal("IDAT", chunks[1].Type);
    Assert.Equal("IEND", chunks[^1].Type);
    Assert.Equal(png.Length, chunks[^1].Offset + 12);
  }

  [Fact]
  public void LargeNoisyImageIsSplitIntoSeveralIdatChunks()
  {
    byte[] png = PngEncoder.Default.Encode(PngTestFiles.RandomImage(300, 300, 3));
    Assert.True(Array.FindAll(PngTestFiles.Chunks(png), c => c.Type == "IDAT").Length > 1);
  }

  [Fact]
  public void FloatImageIsQuantizedWithGamma()
  {
    FloatImage img = new(2, 1);
    img.SetPixel(0, 0, [0.5, 1.0, 0.0]);
    img.SetPixel(1, 0, [0.2, 2.0, -1.0]);
    using MemoryStream ms = new();
    PngEncoder.Default.Encode(img, 2.2, ms);
    Rgb8Image decoded = TestDecode.Png(ms.ToArray());
    Assert.Equal(Rgb8Image.FromFloatImage(img, 2.2).Data, decoded.Data);
    Assert.Equal((186, 255, 0), ((int, int, int))decoded.GetPixel(0, 0));
  }

  [Fact]
  public void BufferLengthMismatchIsRejected()
  {
    using MemoryStream ms = new();
    var ex = Assert.Throws<ArgumentException>(() => PngEncoder.Default.EncodeRgb(new byte[20], 7, 1, ms));
    Assert.Contains("21", ex.Message);
    Assert.Throws<ArgumentOutOfRangeException>(() => PngEncoder.Default.EncodeRgb([], 0, 1, ms));
  }

  /// <summary>Inflates the IDAT stream and returns the filter byte of every row.</summary>
  private static byte[] FilterBytes(byte[] png, int rowBytes)
  {
    using MemoryStream idat = new();
    foreach (var c in PngTestFiles.Chunks(png))
    {
      if (c.Type == "IDAT")
        idat.Write(png, c.Offset + 8, c.Length);
    }
    idat.Position = 0;
    using ZLibStream z = new(idat, CompressionMode.Decompress);
    using MemoryStream raw = new();
    z.CopyTo(raw);
    byte[] bytes = raw.ToArray();
    byte[] filters = new byte[bytes.Length / (rowBytes + 1)];
    for (int y = 0; y < filters.Length; y++)
      filters[y] = bytes[y * (rowBytes + 1)];
    return filters;
  }
}
