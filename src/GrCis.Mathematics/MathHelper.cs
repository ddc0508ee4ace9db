using System;

namespace OpenTK.Mathematics;

/// <summary>OpenTK's scalar helpers and constants.</summary>
public static partial class MathHelper
{
  // OpenTK declares these constants in single precision, and GrCis scenes use them in double
  // expressions (e.g. RotateX(-MathHelper.PiOver2) gives -1.5707963705…). Keeping the float values
  // reproduces GrCis's geometry exactly (a floor tilted by 4e-8 rad decides checker cells at the horizon).
  /// <summary>π in single precision (OpenTK declares the constants as float).</summary>
  public const float Pi = MathF.PI;
  /// <summary>π/2 in single precision.</summary>
  public const float PiOver2 = Pi / 2;
  /// <summary>π/3 in single precision.</summary>
  public const float PiOver3 = Pi / 3;
  /// <summary>π/4 in single precision.</summary>
  public const float PiOver4 = Pi / 4;
  /// <summary>π/6 in single precision.</summary>
  public const float PiOver6 = Pi / 6;
  /// <summary>2π in single precision.</summary>
  public const float TwoPi = 2 * Pi;
  /// <summary>3π/2 in single precision.</summary>
  public const float ThreePiOver2 = 3 * Pi / 2;
  /// <summary>Euler's number e in single precision.</summary>
  public const float E = MathF.E;
  /// <summary>log₁₀ e in single precision.</summary>
  public const float Log10E = 0.4342945f;
  /// <summary>log₂ e in single precision.</summary>
  public const float Log2E = 1.442695f;

  /// <summary>The angle <paramref name="degrees"/> converted to radians (times π/180).</summary>
  public static double DegreesToRadians(double degrees) => degrees * (Math.PI / 180.0);
  /// <summary>The angle <paramref name="radians"/> converted to degrees (times 180/π).</summary>
  public static double RadiansToDegrees(double radians) => radians * (180.0 / Math.PI);
  /// <summary>The angle <paramref name="degrees"/> converted to radians (times π/180).</summary>
  public static float DegreesToRadians(float degrees) => degrees * (MathF.PI / 180f);
  /// <summary>The angle <paramref name="radians"/> converted to degrees (times 180/π).</summary>
  public static float RadiansToDegrees(float radians) => radians * (180f / MathF.PI);

  /// <summary><paramref name="n"/> limited to [min, max]; with min &gt; max the result is min.</summary>
  public static double Clamp(double n, double min, double max) => Math.Max(Math.Min(n, max), min);
  /// <summary><paramref name="n"/> limited to [min, max]; with min &gt; max the result is min.</summary>
  public static float Clamp(float n, float min, float max) => Math.Max(Math.Min(n, max), min);
  /// <summary><paramref name="n"/> limited to [min, max]; with min &gt; max the result is min.</summary>
  public static int Clamp(int n, int min, int max) => Math.Max(Math.Min(n, max), min);

  // The vectors' Clamp tests min first, then max, component by component (OpenTK's order): with min > max a
  // value below min becomes min and any other value above max becomes max; it never throws.
  internal static float ClampComponent(float n, float min, float max) => n < min ? min : n > max ? max : n;
  internal static double ClampComponent(double n, double min, double max) => n < min ? min : n > max ? max : n;

  /// <summary>Linear interpolation a + t·(b − a): a at t = 0, b at t = 1; t is not clamped.</summary>
  public static double Lerp(double a, double b, double t) => a + (b - a) * t;
  /// <summary>Linear interpolation a + t·(b − a): a at t = 0, b at t = 1; t is not clamped.</summary>
  public static float Lerp(float a, float b, float t) => a + (b - a) * t;

  /// <summary>1 / √x, computed exactly (OpenTK's name; no fast approximation is used).</summary>
  public static double InverseSqrtFast(double x) => 1.0 / Math.Sqrt(x);
  /// <summary>1 / √x, computed exactly (OpenTK's name; no fast approximation is used).</summary>
  public static float InverseSqrtFast(float x) => 1f / MathF.Sqrt(x);

  /// <summary>The smallest power of two ≥ <paramref name="n"/> (1 for 0); a negative n throws
  /// <see cref="System.ArgumentOutOfRangeException"/>.</summary>
  public static long NextPowerOfTwo(long n)
  {
    if (n < 0) throw new ArgumentOutOfRangeException(nameof(n), "Must be non-negative.");
    return (long)Math.Pow(2, Math.Ceiling(Math.Log2(Math.Max(n, 1))));
  }

  /// <summary>The smallest power of two ≥ <paramref name="n"/> (2^⌈log₂ n⌉, so 0 gives 0); a negative n throws
  /// <see cref="System.ArgumentOutOfRangeException"/>.</summary>
  public static float NextPowerOfTwo(float n) => (float)NextPowerOfTwo((double)n);

  /// <summary>The smallest power of two ≥ <paramref name="n"/> (2^⌈log₂ n⌉, so 0 gives 0); a negative n throws
  /// <see cref="System.ArgumentOutOfRangeException"/>.</summary>
  public static double NextPowerOfTwo(double n)
  {
    if (n < 0) throw new ArgumentOutOfRangeException(nameof(n), "Must be non-negative.");
    return Math.Pow(2, Math.Ceiling(Math.Log2(n)));
  }

  /// <summary>n! (1 for n ≤ 1; overflows past 20!, as OpenTK's).</summary>
  public static long Factorial(int n)
  {
    long f = 1;
    for (int i = 2; i <= n; i++) f *= i;
    return f;
  }

  /// <summary>The binomial coefficient C(n, k) = n! / (k! (n − k)!), through <see cref="Factorial(int)"/>, so it
  /// overflows for n &gt; 20.</summary>
  public static long BinomialCoefficient(int n, int k) => Factorial(n) / (Factorial(k) * Factorial(n - k));

  /// <summary>Exchanges the values of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static void Swap(ref double a, ref double b) => (a, b) = (b, a);
  /// <summary>Exchanges the values of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static void Swap(ref float a, ref float b) => (a, b) = (b, a);

  /// <summary>Whether a and b are at most 2^<paramref name="maxDeltaBits"/> representable floats apart.</summary>
  public static bool ApproximatelyEqual(float a, float b, int maxDeltaBits)
  {
    // Map the sign-magnitude bit patterns onto one monotonic integer line, so −0 and +0 meet.
    static long Ordered(float x)
    {
      long bits = BitConverter.SingleToInt32Bits(x);
      return bits < 0 ? int.MinValue - bits : bits;
    }
    return Math.Abs(Ordered(a) - Ordered(b)) <= 1L << maxDeltaBits;
  }

  const double DoubleMinNormal = 2.2250738585072014e-308;
  const float FloatMinNormal = 1.17549435e-38f;

  // OpenTK's epsilon test is relative to |a| + |b|; near zero (where relative error means nothing)
  // it compares the absolute difference with epsilon times the smallest normal number.
  /// <summary>Whether |a − b| is less than <paramref name="epsilon"/> relative to |a| + |b|; when either is 0 or the
  /// difference is below the smallest normal number, the difference is compared with epsilon times that smallest normal
  /// number instead.</summary>
  public static bool ApproximatelyEqualEpsilon(double a, double b, double epsilon)
  {
    if (a == b) return true;
    double diff = Math.Abs(a - b);
    if (a == 0 || b == 0 || diff < DoubleMinNormal)
      return diff < epsilon * DoubleMinNormal;
    return diff / Math.Min(Math.Abs(a) + Math.Abs(b), double.MaxValue) < epsilon;
  }

  /// <summary>Whether |a − b| is less than <paramref name="epsilon"/> relative to |a| + |b|; when either is 0 or the
  /// difference is below the smallest normal number, the difference is compared with epsilon times that smallest normal
  /// number instead.</summary>
  public static bool ApproximatelyEqualEpsilon(float a, float b, float epsilon)
  {
    if (a == b) return true;
    float diff = Math.Abs(a - b);
    if (a == 0 || b == 0 || diff < FloatMinNormal)
      return diff < epsilon * FloatMinNormal;
    return diff / Math.Min(Math.Abs(a) + Math.Abs(b), float.MaxValue) < epsilon;
  }

  /// <summary>Absolute tolerance (equal infinities count as equivalent).</summary>
  public static bool ApproximatelyEquivalent(double a, double b, double tolerance) => a == b || Math.Abs(a - b) <= tolerance;
  /// <summary>Whether a and b are equal or at most <paramref name="tolerance"/> apart (an absolute
  /// tolerance).</summary>
  public static bool ApproximatelyEquivalent(float a, float b, float tolerance) => a == b || Math.Abs(a - b) <= tolerance;
}
