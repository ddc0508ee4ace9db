using System;
using System.Buffers.Binary;
using System.Globalization;
using System.IO;
using System.Text;
using Rendering.Imaging;

namespace Rendering.Tests.Imaging;

public class PfmWriterTests
{
  [Fact]
  public void RgbHeaderAndBottomUpLittleEndianRows()
  {
    FloatImage img = new(2, 3);
    img.SetPixel(0, 2, [1.5, -2.0, 0.25]);   // bottom-left: first pixel in the file
    img.SetPixel(1, 0, [7.0, 8.0, 9.0]);     // top-right: last pixel in the file
    byte[] pfm = PfmWriter.Encode(img);

    byte[] header = Encoding.ASCII.GetBytes("PF\n2 3\n-1.0\n");
    Assert.Equal(header, pfm[..header.Length]);
    Assert.Equal(header.Length + 2 * 3 * 3 * 4, pfm.Length);
    Assert.Equal(new byte[] { 0x00, 0x00, 0xC0, 0x3F }, pfm[header.Length..(header.Length + 4)]); // 1.5f LE
    Assert.Equal(-2.0f, BinaryPrimitives.ReadSingleLittleEndian(pfm.AsSpan(header.Length + 4)));
    Assert.Equal(0.25f, BinaryPrimitives.ReadSingleLittleEndian(pfm.AsSpan(header.Length + 8)));
    Assert.Equal(9.0f, BinaryPrimitives.ReadSingleLittleEndian(pfm.AsSpan(pfm.Length - 4)));
  }

  [Fact]
  public void GrayImageUsesLowercaseMagic()
  {
    FloatImage img = new(4, 1, 1);
    img[3, 0, 0] = 0.5f;
    byte[] pfm = PfmWriter.Encode(img);
    byte[] header = Encoding.ASCII.GetBytes("Pf\n4 1\n-1.0\n");
    Assert.Equal(header, pfm[..header.Length]);
    Assert.Equal(header.Length + 16, pfm.Length);
    Assert.Equal(0.5f, BinaryPrimitives.ReadSingleLittleEndian(pfm.AsSpan(pfm.Length - 4)));
  }

  [Fact]
  public void OtherBandCountsAreRejected()
  {
    Assert.Throws<ArgumentException>(() => PfmWriter.Encode(new FloatImage(1, 1, 4)));
  }

  [Fact]
  public void HeaderIgnoresCurrentCulture()
  {
    CultureInfo saved = CultureInfo.CurrentCulture;
    try
    {
      CultureInfo.CurrentCulture = new CultureInfo("de-DE");
      Assert.StartsWith("PF\n1 1\n-1.0\n", Encoding.ASCII.GetString(PfmWriter.Encode(new FloatImage(1, 1))));
    }
    finally
    {
      CultureInfo.CurrentCulture = saved;
    }
  }

  [Fact]
  public void SaveWritesFileAtomically()
  {
    string dir = Directory.CreateTempSubdirectory("pfm-test-").FullName;
    try
    {
      string path = Path.Combine(dir, "out.pfm");
      FloatImage img = new(3, 2);
      PfmWriter.Save(path, img);
      Assert.Equal(PfmWriter.Encode(img), File.ReadAllBytes(path));
      Assert.Single(Directory.GetFiles(dir));
    }
    finally
    {
      Directory.Delete(dir, recursive: true);
    }
  }
}
