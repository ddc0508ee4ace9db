using System;
using System.Drawing;

namespace MathSupport;

/// <summary>GrCis's HSV colour conversions: hue in degrees [0, 360), saturation and value 0 to 1 (RGB 0 to 1 or bytes).</summary>
public partial class Arith
{
  /// <summary>Hue, saturation and value of a colour; the hue as <see cref="Color.GetHue"/> computes it.</summary>
  public static void ColorToHSV(Color color, out double hue, out double saturation, out double value)
  {
    int max = Math.Max(color.R, Math.Max(color.G, color.B));
    int min = Math.Min(color.R, Math.Min(color.G, color.B));
    hue = color.GetHue();
    saturation = max == 0 ? 0.0 : 1.0 - min / (double)max;
    value = max / 255.0;
  }

  /// <summary>The colour of (hue, saturation, value), each channel rounded to a byte.</summary>
  public static Color HSVToColor(double hue, double saturation, double value)
  {
    HSVtoRGB(hue, saturation, value, out double r, out double g, out double b);
    static int Byte(double c) => Clamp(Convert.ToInt32(c * 255.0), 0, 255);
    return Color.FromArgb(Byte(r), Byte(g), Byte(b));
  }

  public static void RGBtoHSV(double R, double G, double B, out double hue, out double saturation, out double value)
  {
    double max = Math.Max(R, Math.Max(G, B)), min = Math.Min(R, Math.Min(G, B)), delta = max - min;
    saturation = max <= 0.0 ? 0.0 : delta / max;
    value = max;
    hue = 0.0;
    if (delta <= 0.0)
      return;
    // Sector by the largest channel, then to degrees in [0, 360).
    hue = R == max ? (G - B) / delta : G == max ? 2.0 + (B - R) / delta : 4.0 + (R - G) / delta;
    hue *= 60.0;
    if (hue < 0.0)
      hue += 360.0;
    else if (hue >= 360.0)
      hue -= 360.0;
  }

  public static void RGBtoHSV(float R, float G, float B, out float hue, out float saturation, out float value)
  {
    RGBtoHSV((double)R, G, B, out double h, out double s, out double v);
    (hue, saturation, value) = ((float)h, (float)s, (float)v);
  }

  /// <summary>GrCis's name of <see cref="HSVtoRGB(double, double, double, out double, out double, out double)"/> from October 2019 to October 2020.</summary>
  public static void HSVToRGB(double hue, double saturation, double value, out double R, out double G, out double B) =>
    HSVtoRGB(hue, saturation, value, out R, out G, out B);

  /// <summary>RGB of (hue in degrees, any real number; saturation; value), negative results clamped to 0.</summary>
  public static void HSVtoRGB(double hue, double saturation, double value, out double R, out double G, out double B)
  {
    double sector = Math.Floor(hue / 60.0);
    int hi = (int)(((long)sector % 6 + 6) % 6);
    double f = hue / 60.0 - sector;
    double v = Math.Max(value, 0.0);
    double p = Math.Max(value * (1.0 - saturation), 0.0);
    double q = Math.Max(value * (1.0 - f * saturation), 0.0);
    double t = Math.Max(value * (1.0 - (1.0 - f) * saturation), 0.0);
    (R, G, B) = hi switch
    {
      0 => (v, t, p),
      1 => (q, v, p),
      2 => (p, v, t),
      3 => (p, q, v),
      4 => (t, p, v),
      _ => (v, p, q),
    };
  }

  public static void HSVtoRGB(float hue, float saturation, float value, out float R, out float G, out float B)
  {
    HSVtoRGB((double)hue, saturation, value, out double r, out double g, out double b);
    (R, G, B) = ((float)r, (float)g, (float)b);
  }
}
