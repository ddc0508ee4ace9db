using System;

namespace OpenTK.Mathematics;

/// <summary>OpenTK's scalar helpers and constants.</summary>
public static class MathHelper
{
  public const double Pi = Math.PI;
  public const double PiOver2 = Math.PI / 2.0;
  public const double PiOver3 = Math.PI / 3.0;
  public const double PiOver4 = Math.PI / 4.0;
  public const double PiOver6 = Math.PI / 6.0;
  public const double TwoPi = 2.0 * Math.PI;
  public const double ThreePiOver2 = 3.0 * Math.PI / 2.0;
  public const double E = Math.E;
  public const double Log10E = 0.4342944819032518;
  public const double Log2E = 1.4426950408889634;

  public static double DegreesToRadians(double degrees) => degrees * (Math.PI / 180.0);
  public static double RadiansToDegrees(double radians) => radians * (180.0 / Math.PI);
  public static float DegreesToRadians(float degrees) => degrees * (MathF.PI / 180f);
  public static float RadiansToDegrees(float radians) => radians * (180f / MathF.PI);

  public static double Clamp(double n, double min, double max) => Math.Max(Math.Min(n, max), min);
  public static float Clamp(float n, float min, float max) => Math.Max(Math.Min(n, max), min);
  public static int Clamp(int n, int min, int max) => Math.Max(Math.Min(n, max), min);

  public static double Lerp(double a, double b, double t) => a + (b - a) * t;
  public static float Lerp(float a, float b, float t) => a + (b - a) * t;

  public static double InverseSqrtFast(double x) => 1.0 / Math.Sqrt(x);
  public static float InverseSqrtFast(float x) => 1f / MathF.Sqrt(x);

  public static long NextPowerOfTwo(long n)
  {
    if (n < 0) throw new ArgumentOutOfRangeException(nameof(n), "Must be non-negative.");
    return (long)Math.Pow(2, Math.Ceiling(Math.Log2(Math.Max(n, 1))));
  }

  public static bool ApproximatelyEqualEpsilon(double a, double b, double epsilon) => Math.Abs(a - b) <= epsilon;
}
