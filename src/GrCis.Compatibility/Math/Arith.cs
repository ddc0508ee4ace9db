using System;

namespace MathSupport;

/// <summary>GrCis's small arithmetic helpers.</summary>
public partial class Arith
{
  /// <summary><paramref name="val"/> limited to [<paramref name="min"/>, <paramref name="max"/>].</summary>
  public static T Clamp<T>(T val, T min, T max) where T : IComparable<T> =>
    val.CompareTo(min) < 0 ? min : val.CompareTo(max) > 0 ? max : val;

  /// <summary><paramref name="a"/> to an integer power (negative powers too) by repeated squaring.</summary>
  public static double Pow(double a, int e) => Geometry.IntPow(a, e);

  /// <summary>Non-negative remainder for a positive <paramref name="b"/>.</summary>
  public static int Mod(int a, int b)
  {
    int m = a % b;
    return m < 0 ? m + b : m;
  }

  public static double DegreeToRadian(double deg) => deg * (Math.PI / 180.0);

  public static double RadianToDegree(double rad) => rad * (180.0 / Math.PI);

  /// <summary>Greatest common divisor of two whole numbers held in doubles.</summary>
  public static double GCD(double a, double b)
  {
    a = Math.Abs(Math.Round(a));
    b = Math.Abs(Math.Round(b));
    while (b > 0.0)
      (a, b) = (b, a % b);
    return a;
  }

  public static long GCD(long a, long b)
  {
    a = Math.Abs(a);
    b = Math.Abs(b);
    while (b != 0)
      (a, b) = (b, a % b);
    return a;
  }

  /// <summary>
  /// Where the ray (ox, oy) + t·(dx, dy) crosses the segment from (ax, ay) to (bx, by): the parameter t (negative
  /// when the crossing is behind the origin), or <see cref="double.NegativeInfinity"/> when the ray misses the
  /// segment or runs parallel to it.
  /// </summary>
  public static double RaySegment2D(double ox, double oy, double dx, double dy, double ax, double ay, double bx, double by)
  {
    // Solve o + t·d = a + s·(b − a) by Cramer's rule (2D cross products).
    double ex = bx - ax, ey = by - ay;
    double den = dx * ey - dy * ex;
    if (den == 0.0)
      return double.NegativeInfinity;
    double px = ax - ox, py = ay - oy;
    double t = (px * ey - py * ex) / den;
    double s = (px * dy - py * dx) / den;
    return s >= 0.0 && s <= 1.0 ? t : double.NegativeInfinity;
  }
}
