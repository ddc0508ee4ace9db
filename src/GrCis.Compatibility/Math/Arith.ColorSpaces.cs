using System;
using System.Drawing;

namespace MathSupport;

/// <summary>
/// GrCis's CIE L*a*b* conversions of sRGB colours (reference white D50, Bradford-adapted sRGB matrices, after
/// Bruce Lindbloom's formulae) and Radiance's RGBe encoding of HDR colours (three 8-bit mantissas, one shared exponent).
/// </summary>
public partial class Arith
{
  // D50 white in XYZ.
  const double WhiteX = 0.964221, WhiteY = 1.0, WhiteZ = 0.825211;

  // CIE's ε = (6/29)³ and κ = (29/3)³: the Lab curve is linear below ε.
  const double LabEpsilon = 216.0 / 24389.0, LabKappa = 24389.0 / 27.0;

  /// <summary>L* (0 to 100), a* and b* of an 8-bit sRGB colour.</summary>
  public static void ColorToCIELab(Color color, out double L, out double A, out double B)
  {
    double r = SrgbToLinear(color.R / 255.0), g = SrgbToLinear(color.G / 255.0), b = SrgbToLinear(color.B / 255.0);
    double fx = LabCurve((0.4360747 * r + 0.3850649 * g + 0.1430804 * b) / WhiteX);
    double fy = LabCurve((0.2225045 * r + 0.7168786 * g + 0.0606169 * b) / WhiteY);
    double fz = LabCurve((0.0139322 * r + 0.0971045 * g + 0.7141733 * b) / WhiteZ);
    L = 116.0 * fy - 16.0;
    A = 500.0 * (fx - fy);
    B = 200.0 * (fy - fz);
  }

  /// <summary>The 8-bit sRGB colour of (L*, a*, b*), each channel rounded and clamped to 0–255.</summary>
  public static Color CIELabToColor(double L, double A, double B)
  {
    double fy = (L + 16.0) / 116.0;
    double fx = fy + A / 500.0;
    double fz = fy - B / 200.0;
    double x = LabCurveInverse(fx) * WhiteX;
    // Y straight from L* keeps dark greys exact.
    double y = (L > LabKappa * LabEpsilon ? fy * fy * fy : L / LabKappa) * WhiteY;
    double z = LabCurveInverse(fz) * WhiteZ;

    static int Byte(double linear) => Clamp((int)Math.Round(LinearToSrgb(linear) * 255.0), 0, 255);
    return Color.FromArgb(
      Byte(3.1338561 * x - 1.6168667 * y - 0.4906146 * z),
      Byte(-0.9787684 * x + 1.9161415 * y + 0.0334540 * z),
      Byte(0.0719453 * x - 0.2289914 * y + 1.4052427 * z));
  }

  static double SrgbToLinear(double c) => c <= 0.04045 ? c / 12.92 : Math.Pow((c + 0.055) / 1.055, 2.4);

  static double LinearToSrgb(double c) => c <= 0.0031308 ? 12.92 * c : 1.055 * Math.Pow(c, 1.0 / 2.4) - 0.055;

  static double LabCurve(double t) => t > LabEpsilon ? Math.Cbrt(t) : (LabKappa * t + 16.0) / 116.0;

  static double LabCurveInverse(double f)
  {
    double cube = f * f * f;
    return cube > LabEpsilon ? cube : (116.0 * f - 16.0) / LabKappa;
  }

  /// <summary>
  /// Decodes the RGBe pixel at <paramref name="startRgbe"/> into three floats at <paramref name="startRgb"/>: each
  /// channel is (mantissa + ½)·2^(e − 136); exponent byte 0 is black. Out-of-range offsets change nothing.
  /// </summary>
  public static void RGBeToRGB(byte[]? rgbe, int startRgbe, float[]? rgb, int startRgb)
  {
    if (rgbe == null || startRgbe < 0 || startRgbe + 4 > rgbe.Length || rgb == null || startRgb < 0 || startRgb + 3 > rgb.Length)
      return;
    int e = rgbe[startRgbe + 3];
    double scale = e == 0 ? 0.0 : Math.ScaleB(1.0, e - 136);
    for (int i = 0; i < 3; i++)
      rgb[startRgb + i] = e == 0 ? 0.0f : (float)((rgbe[startRgbe + i] + 0.5) * scale);
  }

  /// <summary>
  /// Encodes (R, G, B) as an RGBe pixel at <paramref name="startRgbe"/>: the largest channel sets a shared power
  /// of two, each channel keeps 8 bits below it. Colours below 1e-32 are black (all four bytes 0), negative channels
  /// count as 0, colours too bright for the exponent saturate. An out-of-range offset changes nothing.
  /// </summary>
  public static void RGBToRGBe(byte[]? rgbe, int startRgbe, double R, double G, double B)
  {
    if (rgbe == null || startRgbe < 0 || startRgbe + 4 > rgbe.Length)
      return;
    double max = Math.Max(Math.Max(R, G), B);
    if (!(max >= 1.0e-32))
    {
      Array.Clear(rgbe, startRgbe, 4);
      return;
    }
    // max = m · 2^exp with m in [0.5, 1).
    int exp = Math.Min(Math.ILogB(max) + 1, 127);
    double scale = Math.ScaleB(256.0, -exp);
    static byte Mantissa(double c, double scale) => (byte)Math.Clamp(c * scale, 0.0, 255.0);
    rgbe[startRgbe] = Mantissa(R, scale);
    rgbe[startRgbe + 1] = Mantissa(G, scale);
    rgbe[startRgbe + 2] = Mantissa(B, scale);
    rgbe[startRgbe + 3] = (byte)(exp + 128);
  }
}
