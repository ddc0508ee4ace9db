using System;
using System.Buffers.Binary;
using System.IO;
using System.Linq;
using System.Text;
using Rendering.Imaging;
using StbImageWriteSharp;

namespace Rendering.Tests.Imaging;

public sealed class ImageFileTests : IDisposable
{
  readonly string _dir = Directory.CreateTempSubdirectory("grcis-imagefile-").FullName;

  public void Dispose() => Directory.Delete(_dir, recursive: true);

  string Write(string name, Action<Stream> write)
  {
    string path = Path.Combine(_dir, name);
    using (FileStream fs = File.Create(path))
      write(fs);
    return path;
  }

  static readonly byte[] Pixels = [0, 51, 255, 255, 128, 0, 10, 20, 30, 200, 100, 50];

  [Theory]
  [InlineData("png")]
  [InlineData("bmp")]
  [InlineData("tga")]
  public void LosslessFormatsLoadToTheStoredBytesOverTwoHundredFiftyFive(string ext)
  {
    string path = Write("a." + ext, s =>
    {
      var w = new ImageWriter();
      if (ext == "png") w.WritePng(Pixels, 2, 2, ColorComponents.RedGreenBlue, s);
      else if (ext == "bmp") w.WriteBmp(Pixels, 2, 2, ColorComponents.RedGreenBlue, s);
      else w.WriteTga(Pixels, 2, 2, ColorComponents.RedGreenBlue, s);
    });
    Assert.Equal(Pixels, ImageFile.LoadRgb8(path).Data);
    FloatImage f = ImageFile.Load(path);
    Assert.Equal((2, 2, 3), (f.Width, f.Height, f.Bands));
    for (int i = 0; i < Pixels.Length; i++)
      Assert.Equal((float)(Pixels[i] / 255.0), f.Data[i]);
  }

  [Fact]
  public void JpegLoadsCloseToTheOriginal()
  {
    byte[] flat = new byte[16 * 16 * 3];
    for (int i = 0; i < flat.Length; i += 3)
      (flat[i], flat[i + 1], flat[i + 2]) = (200, 100, 50);
    string path = Write("a.jpg", s => new ImageWriter().WriteJpg(flat, 16, 16, ColorComponents.RedGreenBlue, s, 95));
    Rgb8Image img = ImageFile.LoadRgb8(path);
    Assert.Equal(16, img.Width);
    Assert.All(img.Data, (b, i) => Assert.InRange(b, flat[i] - 4, flat[i] + 4));
  }

  [Fact]
  public void HdrLoadsLinearValuesAboveOne()
  {
    // Flat (not run-length) RGBE: mantissas m with shared exponent e mean m * 2^(e - 136).
    float[] hdr = [4.0f, 0.5f, 0.25f, 1.0f, 2.0f, 8.0f];
    byte[] rgbe = [128, 16, 8, 131, 16, 32, 128, 132];
    string path = Write("a.hdr", s =>
    {
      s.Write("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n"u8);
      s.Write(rgbe);
    });
    FloatImage f = ImageFile.Load(path, gamma: 2.2);   // gamma applies to 8-bit files only
    Assert.Equal((2, 1), (f.Width, f.Height));
    for (int i = 0; i < hdr.Length; i++)
      Assert.Equal(hdr[i], f.Data[i]);
  }

  [Fact]
  public void GammaLinearizesEightBitValues()
  {
    string path = Path.Combine(_dir, "g.png");
    PngFile.Save(path, new Rgb8Image(1, 1, [128, 255, 0]));
    FloatImage f = ImageFile.Load(path, gamma: 2.2);
    Assert.Equal((float)Math.Pow(128 / 255.0, 2.2), f.Data[0]);
    Assert.Equal(1f, f.Data[1]);
    Assert.Equal(0f, f.Data[2]);
  }

  [Theory]
  [InlineData(true)]
  [InlineData(false)]
  public void PfmReadsBothByteOrdersWithRowsBottomToTop(bool littleEndian)
  {
    // 1x2 image: stored bottom row (y = 1) first.
    float[] bottom = [1.5f, -2f, 1e6f], top = [0.25f, 0f, 3f];
    using MemoryStream ms = new();
    ms.Write(Encoding.ASCII.GetBytes(littleEndian ? "PF\n1 2\n-1.0\n" : "PF\n1 2\n1.0\n"));
    foreach (float v in (float[])[.. bottom, .. top])
    {
      byte[] b = new byte[4];
      if (littleEndian) BinaryPrimitives.WriteSingleLittleEndian(b, v);
      else BinaryPrimitives.WriteSingleBigEndian(b, v);
      ms.Write(b);
    }
    string path = Write("a.pfm", s => s.Write(ms.ToArray()));
    FloatImage f = ImageFile.Load(path);
    Assert.Equal(top, f.GetPixel(0, 0).Select(d => (float)d));
    Assert.Equal(bottom, f.GetPixel(0, 1).Select(d => (float)d));
  }

  [Fact]
  public void PfmWriterOutputReadsBackExactly()
  {
    var img = new FloatImage(3, 2);
    for (int i = 0; i < img.Data.Length; i++)
      img.Data[i] = i * 0.37f - 1f;
    string path = Path.Combine(_dir, "w.pfm");
    PfmWriter.Save(path, img);
    Assert.Equal(img.Data, ImageFile.Load(path).Data);

    var gray = new FloatImage(2, 1, 1, [0.5f, 2f]);
    PfmWriter.Save(path, gray);
    Assert.Equal(gray.Data, PfmReader.Load(path).Data);
    Assert.Equal(new[] { 0.5f, 0.5f, 0.5f, 2f, 2f, 2f }, ImageFile.Load(path).Data);
  }

  [Theory]
  [InlineData("PF\n2 2\n-1.0\n\0\0\0\0", "truncated")]
  [InlineData("PF\n0 2\n-1.0\n", "width")]
  [InlineData("PF\n2 2\n0\n", "scale")]
  [InlineData("PF\n2", "header truncated")]
  public void BadPfmIsRejectedNamingTheFile(string content, string reason)
  {
    string path = Write("bad.pfm", s => s.Write(Encoding.ASCII.GetBytes(content)));
    string message = Assert.Throws<InvalidDataException>(() => ImageFile.Load(path)).Message;
    Assert.StartsWith(path + ": ", message);
    Assert.Contains(reason, message);
  }

  [Theory]
  [InlineData(new byte[] { 1, 2, 3 })]
  [InlineData(new byte[] { 137, 80, 78, 71, 13, 10, 26, 10, 0, 0 })]
  [InlineData(new byte[] { (byte)'B', (byte)'M', 0, 0, 0, 0 })]
  public void CorruptFileIsOneMessageStartingWithThePath(byte[] content)
  {
    string path = Write("bad.img", s => s.Write(content));
    string message = Assert.Throws<InvalidDataException>(() => ImageFile.Load(path)).Message;
    Assert.StartsWith(path + ": corrupt or unsupported image", message);
    Assert.DoesNotContain('\n', message);
    Assert.Throws<InvalidDataException>(() => ImageFile.LoadRgb8(path));
  }

  [Fact]
  public void FloatFormatsAreRefusedAsEightBit()
  {
    string path = Path.Combine(_dir, "f.pfm");
    PfmWriter.Save(path, new FloatImage(1, 1));
    Assert.Contains("floating-point", Assert.Throws<InvalidDataException>(() => ImageFile.LoadRgb8(path)).Message);
  }
}
