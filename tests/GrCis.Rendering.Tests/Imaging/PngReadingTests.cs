using System;
using System.IO;
using System.IO.Compression;
using Rendering.Imaging;

namespace Rendering.Tests.Imaging;

/// <summary>PNG reading through StbImageSharp: every colour type and depth the renders and references use, and bad files.</summary>
public class PngReadingTests
{
  // Expected values below are worked out by hand from the PNG spec, not by the library's filter code.
  public static TheoryData<byte, byte[], byte[], byte[]> FilterCases => new()
  {
    // filter, row 0 (stored with filter None), row 1 filtered bytes, row 1 expected gray values
    { 0, [10, 20, 30], [7, 8, 9], [7, 8, 9] },
    { 1, [10, 20, 30], [5, 3, 250], [5, 8, 2] },                    // wraps mod 256
    { 2, [10, 20, 30], [1, 2, 250], [11, 22, 24] },
    { 3, [200, 200, 200], [0, 0, 0], [100, 150, 175] },             // (a + b) must not overflow a byte
    { 3, [10, 20, 30], [1, 2, 3], [6, 15, 25] },
    // Paeth: x0 picks b, x1 picks c, x2 tie pa == pc picks a, x3 tie pb == pc picks b, x4 picks a.
    { 4, [15, 20, 18, 82, 82], [251, 1, 34, 8, 5], [10, 16, 50, 90, 95] },
  };

  [Theory]
  [MemberData(nameof(FilterCases))]
  public void DecodesEachFilterTypeOnGray8(byte filter, byte[] row0, byte[] row1Filtered, byte[] row1Expected)
  {
    int w = row0.Length;
    byte[] stream = [0, .. row0, filter, .. row1Filtered];
    Rgb8Image img = TestDecode.Png(PngTestFiles.FromFilteredRows(w, 2, 8, 0, stream));
    for (int x = 0; x < w; x++)
    {
      Assert.Equal((row0[x], row0[x], row0[x]), img.GetPixel(x, 0));
      Assert.Equal((row1Expected[x], row1Expected[x], row1Expected[x]), img.GetPixel(x, 1));
    }
  }

  [Fact]
  public void SubAndPaethUseThreeBytePixelDistanceOnRgb()
  {
    // Row 0 Sub: second pixel adds the first pixel's same channel, not the previous byte.
    // Row 1 Paeth: first pixel has a = c = 0 so predicts b (above); second pixel channel 0 has
    // a=11, b=11, c=10 (tie pa == pb picks a), channels 1 and 2 pick b.
    byte[] stream = [1, 10, 20, 30, 1, 2, 3, 4, 1, 1, 1, 1, 1, 1];
    Rgb8Image img = TestDecode.Png(PngTestFiles.FromFilteredRows(2, 2, 8, 2, stream));
    Assert.Equal(new byte[] { 10, 20, 30, 11, 22, 33, 11, 21, 31, 12, 23, 34 }, img.Data);
  }

  [Fact]
  public void ImageDataSplitOverManyIdatChunksDecodes()
  {
    Rgb8Image original = PngTestFiles.RandomImage(9, 5, 11);
    byte[] stream = new byte[5 * 28];
    for (int y = 0; y < 5; y++)
      original.Data.AsSpan(y * 27, 27).CopyTo(stream.AsSpan(y * 28 + 1));
    byte[] png = PngTestFiles.FromFilteredRows(9, 5, 8, 2, stream, idatSplit: 7);
    Assert.True(Array.FindAll(PngTestFiles.Chunks(png), c => c.Type == "IDAT").Length > 5);
    Assert.Equal(original.Data, TestDecode.Png(png).Data);
  }

  [Fact]
  public void DecodesGray8()
  {
    byte[] png = PngTestFiles.Encode(3, 1, 8, 0, [0, 128, 255]);
    Assert.Equal(new byte[] { 0, 0, 0, 128, 128, 128, 255, 255, 255 }, TestDecode.Png(png).Data);
  }

  [Fact]
  public void DecodesGray16ByHighByte()
  {
    // StbImageSharp keeps the high byte: 0x00FF -> 0, 0xFE01 -> 254, 0x807F -> 128.
    byte[] png = PngTestFiles.Encode(6, 1, 16, 0, [0x00, 0x00, 0xFF, 0xFF, 0x00, 0xFF, 0xFE, 0x01, 0x12, 0x34, 0x80, 0x7F]);
    Assert.Equal(new byte[] { 0, 255, 0, 254, 18, 128 }, Channel0(TestDecode.Png(png)));
  }

  [Fact]
  public void DecodesRgb16()
  {
    byte[] png = PngTestFiles.Encode(1, 2, 16, 2, [0xFF, 0xFF, 0x00, 0x80, 0x01, 0x00, 0xAB, 0xCD, 0x00, 0x00, 0x12, 0x34]);
    Assert.Equal(new byte[] { 255, 0, 1, 171, 0, 18 }, TestDecode.Png(png).Data);
  }

  [Fact]
  public void DecodesGrayAlphaAndRgba16DroppingAlpha()
  {
    byte[] ga = PngTestFiles.Encode(2, 1, 8, 4, [50, 0, 60, 255]);
    Assert.Equal(new byte[] { 50, 50, 50, 60, 60, 60 }, TestDecode.Png(ga).Data);

    byte[] rgba16 = PngTestFiles.Encode(1, 1, 16, 6, [0x10, 0x00, 0x20, 0x00, 0x30, 0x00, 0x00, 0x00]);
    Assert.Equal(new byte[] { 16, 32, 48 }, TestDecode.Png(rgba16).Data);
  }

  [Fact]
  public void DecodesPalette8()
  {
    byte[] palette = [255, 0, 0, 0, 255, 0, 0, 0, 255];
    byte[] png = PngTestFiles.Encode(4, 1, 8, 3, [2, 0, 1, 2], palette);
    Assert.Equal(new byte[] { 0, 0, 255, 255, 0, 0, 0, 255, 0, 0, 0, 255 }, TestDecode.Png(png).Data);
  }

  [Fact]
  public void DecodesPalette4WithOddWidth()
  {
    byte[] palette = new byte[16 * 3];
    for (int i = 0; i < 16; i++)
      palette[3 * i] = (byte)(i * 10);
    // Indices 1, 15, 7 per row, high nibble first; the last nibble of each row is padding.
    byte[] png = PngTestFiles.Encode(3, 2, 4, 3, [0x1F, 0x70, 0xF1, 0x0F], palette);
    Rgb8Image img = TestDecode.Png(png);
    Assert.Equal(new byte[] { 10, 150, 70, 150, 10, 0 }, new[] { img.Data[0], img.Data[3], img.Data[6], img.Data[9], img.Data[12], img.Data[15] });
  }

  [Fact]
  public void DecodesSubByteGray()
  {
    // 1-bit, width 10: bits 1010000011 then padding; 2-bit, width 3: 0,1,3 -> 0, 85, 255.
    byte[] png1 = PngTestFiles.Encode(10, 1, 1, 0, [0b1010_0000, 0b1100_0000]);
    byte[] gray1 = Channel0(TestDecode.Png(png1));
    Assert.Equal(new byte[] { 255, 0, 255, 0, 0, 0, 0, 0, 255, 255 }, gray1);

    byte[] png2 = PngTestFiles.Encode(3, 1, 2, 0, [0b00_01_11_00]);
    Assert.Equal(new byte[] { 0, 85, 255 }, Channel0(TestDecode.Png(png2)));
  }


  [Fact]
  public void PaletteImageWithoutPlteIsRejected()
  {
    byte[] png = PngTestFiles.FromFilteredRows(1, 1, 8, 3, [0, 0]);
    Assert.Contains("PLTE", Assert.Throws<InvalidDataException>(() => TestDecode.Png(png)).Message);
  }



  [Fact]
  public void TruncatedFileIsRejectedAtEveryCutBeforeTheEndChunk()
  {
    byte[] png = PngEncoder.Default.Encode(PngTestFiles.RandomImage(7, 3, 2));
    // Every cut before the end chunk loses pixels; the reader does not insist on IEND itself.
    int iend = Array.Find(PngTestFiles.Chunks(png), c => c.Type == "IEND").Offset;
    for (int len = 0; len < iend; len++)
    {
      byte[] cut = png[..len];
      Assert.Throws<InvalidDataException>(() => TestDecode.Png(cut));
    }
  }

  [Fact]
  public void TruncatedZlibStreamWithValidChunksIsRejected()
  {
    using MemoryStream z = new();
    using (ZLibStream zlib = new(z, CompressionLevel.Optimal, leaveOpen: true))
      zlib.Write(new byte[4 * 10]);
    byte[] half = z.ToArray()[..(int)(z.Length / 2)];
    Assert.Throws<InvalidDataException>(() => TestDecode.Png(PngTestFiles.Assemble(3, 4, 8, 0, half)));
  }

  [Fact]
  public void TooLittleImageDataIsRejected()
  {
    byte[] png = PngTestFiles.FromFilteredRows(3, 2, 8, 0, [0, 1, 2, 3]);
    Assert.Throws<InvalidDataException>(() => TestDecode.Png(png));
  }

  [Fact]
  public void GarbageZlibDataIsRejected()
  {
    byte[] png = PngTestFiles.Assemble(2, 2, 8, 0, [0x78, 0x9C, 0xFF, 0xFF, 0xFF, 0xFF, 0x00, 0x11]);
    Assert.Throws<InvalidDataException>(() => TestDecode.Png(png));
  }

  [Fact]
  public void InvalidFilterTypeIsRejected()
  {
    byte[] png = PngTestFiles.FromFilteredRows(2, 1, 8, 0, [5, 1, 2]);
    Assert.Throws<InvalidDataException>(() => TestDecode.Png(png));
  }


  [Theory]
  [InlineData(8, 5)]
  [InlineData(16, 3)]
  public void InvalidHeaderCombinationsAreRejected(byte depth, byte colorType)
  {
    byte[] png = PngTestFiles.FromFilteredRows(1, 1, depth, colorType, [0, 0, 0, 0, 0, 0, 0]);
    Assert.Throws<InvalidDataException>(() => TestDecode.Png(png));
  }

  [Fact]
  public void NonPngIsRejected()
  {
    Assert.Throws<InvalidDataException>(() => TestDecode.Png("GIF89a-not-a-png"u8));
  }

  [Fact]
  public void UnknownCriticalChunkIsRejectedButAncillaryIgnored()
  {
    byte[] good = PngEncoder.Default.Encode(new Rgb8Image(1, 1));
    Assert.Equal(new byte[3], TestDecode.Png(InsertBeforeIdat(good, "tEXt")).Data);
    Assert.Throws<InvalidDataException>(() => TestDecode.Png(InsertBeforeIdat(good, "ABCD")));
  }

  [Fact]
  public void HugeDeclaredSizeIsRejectedBeforeAllocating()
  {
    byte[] png = PngTestFiles.FromFilteredRows(1_000_000, 1_000_000, 8, 2, [0]);
    Assert.Throws<InvalidDataException>(() => TestDecode.Png(png));
  }

  [Fact]
  public void DecodesFromStream()
  {
    Rgb8Image original = PngTestFiles.RandomImage(4, 4, 9);
    using MemoryStream ms = new(PngEncoder.Default.Encode(original));
    Assert.True(original.ContentEquals(TestDecode.Png(ms)));
  }

  private static byte[] Channel0(Rgb8Image img)
  {
    byte[] c = new byte[img.Width * img.Height];
    for (int i = 0; i < c.Length; i++)
      c[i] = img.Data[3 * i];
    return c;
  }

  private static byte[] InsertBeforeIdat(byte[] png, string type)
  {
    int at = Array.Find(PngTestFiles.Chunks(png), c => c.Type == "IDAT").Offset;
    using MemoryStream ms = new();
    ms.Write(png, 0, at);
    PngTestFiles.WriteChunk(ms, type, "hello"u8);
    ms.Write(png, at, png.Length - at);
    return ms.ToArray();
  }
}
