using System;

namespace GrCis.Interactive;

/// <summary>Blue → cyan → green → yellow → red, for counts and angles.</summary>
internal static class HeatPalette
{
  public static void Color(double t, Span<double> rgb)
  {
    t = double.IsNaN(t) ? 0.0 : Math.Clamp(t, 0.0, 1.0);
    double s = 4.0 * t;
    int seg = Math.Min(3, (int)s);
    double f = s - seg;
    (rgb[0], rgb[1], rgb[2]) = seg switch
    {
      0 => (0.0, f, 1.0),
      1 => (0.0, 1.0, 1.0 - f),
      2 => (f, 1.0, 0.0),
      _ => (1.0, 1.0 - f, 0.0),
    };
  }
}
