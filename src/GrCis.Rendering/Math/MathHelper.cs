using System;

namespace OpenTK.Mathematics;

/// <summary>OpenTK's scalar helpers and constants.</summary>
public static class MathHelper
{
  // OpenTK declares these constants in single precision, and GrCis scenes use them in double
  // expressions (e.g. RotateX(-MathHelper.PiOver2) gives -1.5707963705…). Keeping the float values
  // reproduces GrCis's geometry exactly (a floor tilted by 4e-8 rad decides checker cells at the horizon).
  public const float Pi = MathF.PI;
  public const float PiOver2 = Pi / 2;
  public const float PiOver3 = Pi / 3;
  public const float PiOver4 = Pi / 4;
  public const float PiOver6 = Pi / 6;
  public const float TwoPi = 2 * Pi;
  public const float ThreePiOver2 = 3 * Pi / 2;
  public const float E = MathF.E;
  public const float Log10E = 0.4342945f;
  public const float Log2E = 1.442695f;

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
