using System;
using System.IO;
using Rendering.Imaging;

namespace Rendering.Tests.Imaging;

public class ImageComparisonTests
{
  [Fact]
  public void IdenticalImagesHaveInfinitePsnr()
  {
    Rgb8Image a = PngTestFiles.RandomImage(7, 3, 1);
    Rgb8Image b = new(7, 3, (byte[])a.Data.Clone());
    Assert.Equal(double.PositiveInfinity, ImageComparison.Psnr(a, b));
    Assert.Equal(0.0, ImageComparison.MeanSquaredError(a, b));
    Assert.Equal(0, ImageComparison.MaxChannelDifference(a, b));
  }

  [Fact]
  public void ConstantOffsetOfOneGives48Point13Db()
  {
    Rgb8Image a = PngTestFiles.RandomImage(16, 9, 2);
    byte[] shifted = (byte[])a.Data.Clone();
    for (int i = 0; i < shifted.Length; i++)
      shifted[i] = shifted[i] == 255 ? (byte)254 : (byte)(shifted[i] + 1);
    Rgb8Image b = new(16, 9, shifted);
    Assert.Equal(1.0, ImageComparison.MeanSquaredError(a, b));
    Assert.Equal(48.1308, ImageComparison.Psnr(a, b), 4);   // 20 log10(255)
    Assert.Equal(1, ImageComparison.MaxChannelDifference(a, b));
  }

  [Fact]
  public void SingleChannelFullScaleError()
  {
    Rgb8Image a = new(1, 1);
    Rgb8Image b = new(1, 1);
    b.SetPixel(0, 0, 0, 255, 0);
    Assert.Equal(255.0 * 255.0 / 3.0, ImageComparison.MeanSquaredError(a, b), 9);
    Assert.Equal(4.7712, ImageComparison.Psnr(a, b), 4);     // 10 log10(3)
    Assert.Equal(255, ImageComparison.MaxChannelDifference(b, a));
  }

  [Fact]
  public void SizeMismatchIsRejected()
  {
    var ex = Assert.Throws<ArgumentException>(() => ImageComparison.Psnr(new Rgb8Image(2, 3), new Rgb8Image(3, 2)));
    Assert.Contains("2x3 vs 3x2", ex.Message);
  }

  [Fact]
  public void DifferenceIsStretchedToFullRange()
  {
    Rgb8Image a = new(1, 1, [10, 20, 30]);
    Rgb8Image b = new(1, 1, [10, 22, 26]);
    Assert.Equal(new byte[] { 0, 128, 255 }, ImageComparison.Difference(a, b).Data);
    Assert.Equal(new byte[] { 0, 20, 40 }, ImageComparison.Difference(a, b, 10).Data);
    Assert.Equal(new byte[] { 0, 255, 255 }, ImageComparison.Difference(a, b, 200).Data);
    Assert.Equal(new byte[3], ImageComparison.Difference(a, a).Data);
    Assert.Throws<ArgumentOutOfRangeException>(() => ImageComparison.Difference(a, b, 0));
  }

  [Fact]
  public void SaveDifferenceWritesDecodablePng()
  {
    string dir = Directory.CreateTempSubdirectory("diff-test-").FullName;
    try
    {
      Rgb8Image a = PngTestFiles.RandomImage(5, 4, 3);
      Rgb8Image b = PngTestFiles.RandomImage(5, 4, 4);
      string path = Path.Combine(dir, "diff.png");
      ImageComparison.SaveDifference(path, a, b);
      Assert.Equal(ImageComparison.Difference(a, b).Data, PngFile.Load(path).Data);
    }
    finally
    {
      Directory.Delete(dir, recursive: true);
    }
  }
}
