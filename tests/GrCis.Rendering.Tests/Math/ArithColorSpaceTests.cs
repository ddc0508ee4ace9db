using System;
using System.Drawing;
using MathSupport;

namespace GrCis.Rendering.Tests.MathTypes;

/// <summary>GrCis's CIE L*a*b* (D50) and Radiance RGBe conversions, and the 2D ray–segment test beside them.</summary>
public class ArithColorSpaceTests
{
  // Reference L*a*b* (D50, Bradford) of sRGB colours, from Bruce Lindbloom's colour calculator.
  [Theory]
  [InlineData(255, 255, 255, 100.0, 0.0, 0.0)]
  [InlineData(0, 0, 0, 0.0, 0.0, 0.0)]
  [InlineData(255, 0, 0, 54.2917, 80.8049, 69.8910)]
  [InlineData(0, 255, 0, 87.8181, -79.2873, 80.9902)]
  [InlineData(0, 0, 255, 29.5676, 68.2874, -112.0294)]
  [InlineData(128, 128, 128, 53.5850, 0.0, 0.0)]
  public void ColorToCIELab_matches_reference_values(int r, int g, int b, double L, double A, double B)
  {
    Arith.ColorToCIELab(Color.FromArgb(r, g, b), out double l, out double a, out double bb);
    Assert.Equal(L, l, 0.02);
    Assert.Equal(A, a, 0.02);
    Assert.Equal(B, bb, 0.02);
  }

  [Theory]
  [InlineData(255, 0, 0)]
  [InlineData(12, 200, 99)]
  [InlineData(1, 2, 3)]
  [InlineData(250, 250, 5)]
  [InlineData(77, 77, 77)]
  public void CIELab_round_trips_8_bit_colours(int r, int g, int b)
  {
    Arith.ColorToCIELab(Color.FromArgb(r, g, b), out double l, out double a, out double bb);
    Color back = Arith.CIELabToColor(l, a, bb);
    Assert.Equal((r, g, b), (back.R, back.G, back.B));
  }

  [Fact]
  public void CIELab_outside_the_sRGB_gamut_clamps()
  {
    Color c = Arith.CIELabToColor(50.0, 200.0, 0.0);
    Assert.Equal(255, c.R);
    Assert.Equal(0, c.G);
  }

  [Theory]
  [InlineData(1.0, 1.0, 1.0, new byte[] { 128, 128, 128, 129 })]
  [InlineData(0.5, 0.25, 0.0, new byte[] { 128, 64, 0, 128 })]
  [InlineData(1000.0, 1.0, -3.0, new byte[] { 250, 0, 0, 138 })]
  [InlineData(0.0, 0.0, 0.0, new byte[] { 0, 0, 0, 0 })]
  public void RGBToRGBe_shares_the_largest_channel_exponent(double r, double g, double b, byte[] expected)
  {
    byte[] rgbe = { 9, 9, 9, 9, 9, 9 };
    Arith.RGBToRGBe(rgbe, 1, r, g, b);
    Assert.Equal(9, rgbe[0]);
    Assert.Equal(expected, rgbe[1..5]);
    Assert.Equal(9, rgbe[5]);
  }

  [Theory]
  [InlineData(1.0, 0.5, 0.125)]
  [InlineData(3.7e5, 12.0, 0.0)]
  [InlineData(1e-6, 3e-7, 9e-7)]
  public void RGBe_round_trip_keeps_channels_within_one_step_of_the_shared_scale(double r, double g, double b)
  {
    byte[] rgbe = new byte[4];
    float[] rgb = new float[5];
    Arith.RGBToRGBe(rgbe, 0, r, g, b);
    Arith.RGBeToRGB(rgbe, 0, rgb, 2);
    double step = Math.Max(r, Math.Max(g, b)) / 128.0;
    Assert.Equal(r, rgb[2], step);
    Assert.Equal(g, rgb[3], step);
    Assert.Equal(b, rgb[4], step);
    Assert.Equal(0f, rgb[0]);
  }

  [Fact]
  public void RGBe_ignores_buffers_too_short_and_decodes_exponent_0_as_black()
  {
    byte[] shortBuffer = { 1, 2, 3 };
    Arith.RGBToRGBe(shortBuffer, 0, 1.0, 1.0, 1.0);
    Assert.Equal(new byte[] { 1, 2, 3 }, shortBuffer);
    float[] rgb = { 7f, 7f, 7f };
    Arith.RGBeToRGB(new byte[] { 200, 100, 50, 0 }, 0, rgb, 0);
    Assert.Equal(new[] { 0f, 0f, 0f }, rgb);
    Arith.RGBeToRGB(new byte[] { 200, 100, 50, 0 }, 1, rgb, 0);
  }

  [Theory]
  [InlineData(0, 0, 1, 0, 2, -1, 2, 1, 2.0)]       // straight through the middle
  [InlineData(0, 0, 2, 0, 2, -1, 2, 1, 1.0)]       // t in units of the direction
  [InlineData(0, 0, -1, 0, 2, -1, 2, 1, -2.0)]     // behind the origin: negative t
  [InlineData(0, 0, 1, 1, 0, 2, 2, 0, 1.0)]        // diagonal segment
  [InlineData(0, 0, 1, 0, 2, 0.5, 2, 1, double.NegativeInfinity)]   // passes below the segment
  [InlineData(0, 0, 1, 0, 0, 1, 5, 1, double.NegativeInfinity)]     // parallel
  public void RaySegment2D_returns_the_ray_parameter_or_minus_infinity(
    double ox, double oy, double dx, double dy, double ax, double ay, double bx, double by, double expected) =>
    Assert.Equal(expected, Arith.RaySegment2D(ox, oy, dx, dy, ax, ay, bx, by), 12);
}
