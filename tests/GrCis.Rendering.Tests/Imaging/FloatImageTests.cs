using System;
using Rendering.Imaging;

namespace Rendering.Tests.Imaging;

public class FloatImageTests
{
  [Theory]
  [InlineData(0, 1, 3, "width")]
  [InlineData(1, -1, 3, "height")]
  [InlineData(1, 1, 0, "bands")]
  public void ConstructorRejectsNonPositiveSizes(int w, int h, int bands, string param)
  {
    var ex = Assert.Throws<ArgumentOutOfRangeException>(() => new FloatImage(w, h, bands));
    Assert.Equal(param, ex.ParamName);
  }

  [Fact]
  public void ConstructorRejectsHugeImage()
  {
    var ex = Assert.Throws<ArgumentException>(() => new FloatImage(100_000, 100_000));
    Assert.Contains("exceeds", ex.Message);
  }

  [Fact]
  public void WrappingConstructorChecksBufferLength()
  {
    var ex = Assert.Throws<ArgumentException>(() => new FloatImage(2, 2, 3, new float[11]));
    Assert.Contains("12", ex.Message);
    float[] data = new float[12];
    Assert.Same(data, new FloatImage(2, 2, 3, data).Data);
  }

  [Fact]
  public void PixelsAreRowMajorTopRowFirstInterleaved()
  {
    FloatImage img = new(3, 2);
    img.SetPixel(1, 1, [0.25, 0.5, 0.75]);
    int i = (1 * 3 + 1) * 3;
    Assert.Equal(i, img.PixelIndex(1, 1));
    Assert.Equal([0.25f, 0.5f, 0.75f], img.Data[i..(i + 3)]);
    Assert.Equal(0.5f, img[1, 1, 1]);
    Assert.Equal([0.25, 0.5, 0.75], img.GetPixel(1, 1));

    img[2, 0, 2] = 9f;
    Assert.Equal(9f, img.Data[8]);
  }

  [Fact]
  public void OutOfRangeAccessThrowsWithParameterName()
  {
    FloatImage img = new(3, 2);
    Assert.Equal("x", Assert.Throws<ArgumentOutOfRangeException>(() => img.GetPixel(3, 0)).ParamName);
    Assert.Equal("y", Assert.Throws<ArgumentOutOfRangeException>(() => img.SetPixel(0, -1, [0, 0, 0])).ParamName);
    Assert.Equal("band", Assert.Throws<ArgumentOutOfRangeException>(() => img[0, 0, 3]).ParamName);
  }

  [Fact]
  public void ShortColorArrayIsRejected()
  {
    FloatImage img = new(1, 1);
    Assert.Throws<ArgumentException>(() => img.SetPixel(0, 0, [1.0, 2.0]));
    Assert.Throws<ArgumentException>(() => img.GetPixel(0, 0, new double[2]));
  }

  [Theory]
  [InlineData(0.0, 1.0, 0)]
  [InlineData(1.0, 1.0, 255)]
  [InlineData(0.5, 1.0, 128)]          // 127.5 + 0.5 rounds up
  [InlineData(0.2, 1.0, 51)]
  [InlineData(0.5, 2.2, 186)]          // 0.5^(1/2.2) = 0.7297 -> 186.08
  [InlineData(0.01, 2.2, 31)]          // 0.01^(1/2.2) = 0.1233 -> 31.44
  [InlineData(-0.3, 2.2, 0)]
  [InlineData(1.7, 2.2, 255)]
  [InlineData(double.NaN, 1.0, 0)]
  [InlineData(double.PositiveInfinity, 1.0, 255)]
  public void QuantizationAppliesGammaClampAndRounding(double value, double gamma, int expected)
  {
    FloatImage img = new(1, 1);
    img.SetPixel(0, 0, [value, value, value]);
    Rgb8Image rgb = Rgb8Image.FromFloatImage(img, gamma);
    Assert.Equal(((byte)expected, (byte)expected, (byte)expected), rgb.GetPixel(0, 0));
  }

  [Fact]
  public void OneBandImageBecomesGray()
  {
    FloatImage img = new(2, 1, 1);
    img[1, 0, 0] = 0.2f;
    Rgb8Image rgb = Rgb8Image.FromFloatImage(img);
    Assert.Equal(new byte[] { 0, 0, 0, 51, 51, 51 }, rgb.Data);
  }

  [Theory]
  [InlineData(0.0)]
  [InlineData(-1.0)]
  [InlineData(double.NaN)]
  [InlineData(double.PositiveInfinity)]
  public void InvalidGammaIsRejected(double gamma)
  {
    Assert.Throws<ArgumentOutOfRangeException>(() => Rgb8Image.FromFloatImage(new FloatImage(1, 1), gamma));
  }

  [Fact]
  public void TwoBandImageCannotBecomeRgb()
  {
    Assert.Throws<ArgumentException>(() => Rgb8Image.FromFloatImage(new FloatImage(1, 1, 2)));
  }
}
