using System;

namespace OpenTK.Mathematics;

// OpenTK 4's MathHelper also forwards System.Math's functions, so OpenTK code can call them there; plus MapRange.
public static partial class MathHelper
{
  /// <summary>The absolute value, as <see cref="System.Math"/> computes it.</summary>
  public static decimal Abs(decimal n) => Math.Abs(n);
  /// <summary>The absolute value, as <see cref="System.Math"/> computes it.</summary>
  public static double Abs(double n) => Math.Abs(n);
  /// <summary>The absolute value, as <see cref="System.Math"/> computes it (the minimum value throws
  /// <see cref="System.OverflowException"/>).</summary>
  public static short Abs(short n) => Math.Abs(n);
  /// <summary>The absolute value, as <see cref="System.Math"/> computes it (the minimum value throws
  /// <see cref="System.OverflowException"/>).</summary>
  public static int Abs(int n) => Math.Abs(n);
  /// <summary>The absolute value, as <see cref="System.Math"/> computes it (the minimum value throws
  /// <see cref="System.OverflowException"/>).</summary>
  public static long Abs(long n) => Math.Abs(n);
  /// <summary>The absolute value, as <see cref="System.Math"/> computes it (the minimum value throws
  /// <see cref="System.OverflowException"/>).</summary>
  public static sbyte Abs(sbyte n) => Math.Abs(n);
  /// <summary>The absolute value, as <see cref="System.Math"/> computes it.</summary>
  public static float Abs(float n) => Math.Abs(n);
  /// <summary>The sine of an angle in radians.</summary>
  public static double Sin(double radians) => Math.Sin(radians);
  /// <summary>The hyperbolic sine.</summary>
  public static double Sinh(double radians) => Math.Sinh(radians);
  /// <summary>The arc sine in radians, −π/2..π/2; despite its name, <paramref name="radians"/> is the sine, in [−1,
  /// 1].</summary>
  public static double Asin(double radians) => Math.Asin(radians);
  /// <summary>The cosine of an angle in radians.</summary>
  public static double Cos(double radians) => Math.Cos(radians);
  /// <summary>The hyperbolic cosine.</summary>
  public static double Cosh(double radians) => Math.Cosh(radians);
  /// <summary>The arc cosine in radians, 0..π; despite its name, <paramref name="radians"/> is the cosine, in [−1,
  /// 1].</summary>
  public static double Acos(double radians) => Math.Acos(radians);
  /// <summary>The tangent of an angle in radians.</summary>
  public static double Tan(double radians) => Math.Tan(radians);
  /// <summary>The hyperbolic tangent.</summary>
  public static double Tanh(double radians) => Math.Tanh(radians);
  /// <summary>The arc tangent in radians, −π/2..π/2; despite its name, <paramref name="radians"/> is the
  /// tangent.</summary>
  public static double Atan(double radians) => Math.Atan(radians);
  /// <summary>The angle in radians (−π..π) of the point (x, y) from the positive x axis.</summary>
  public static double Atan2(double y, double x) => Math.Atan2(y, x);
  /// <summary>The full 64-bit product of two 32-bit integers.</summary>
  public static long BigMul(int a, int b) => Math.BigMul(a, b);
  /// <summary>The square root (NaN for a negative number).</summary>
  public static double Sqrt(double n) => Math.Sqrt(n);
  /// <summary>x raised to the power y.</summary>
  public static double Pow(double x, double y) => Math.Pow(x, y);
  /// <summary>The smallest integral value ≥ n.</summary>
  public static decimal Ceiling(decimal n) => Math.Ceiling(n);
  /// <summary>The smallest integral value ≥ n.</summary>
  public static double Ceiling(double n) => Math.Ceiling(n);
  /// <summary>The largest integral value ≤ n.</summary>
  public static decimal Floor(decimal n) => Math.Floor(n);
  /// <summary>The largest integral value ≤ n.</summary>
  public static double Floor(double n) => Math.Floor(n);
  /// <summary>The integral part of n (rounded towards zero).</summary>
  public static decimal Truncate(decimal n) => Math.Truncate(n);
  /// <summary>The integral part of n (rounded towards zero).</summary>
  public static double Truncate(double n) => Math.Truncate(n);
  /// <summary>The natural logarithm ln n.</summary>
  public static double Log(double n) => Math.Log(n);
  /// <summary>The logarithm of n in base <paramref name="newBase"/>.</summary>
  public static double Log(double n, double newBase) => Math.Log(n, newBase);
  /// <summary>The base-10 logarithm.</summary>
  public static double Log10(double n) => Math.Log10(n);
  /// <summary>The base-2 logarithm, computed as <c>Math.Log(n, 2)</c>.</summary>
  public static double Log2(double n) => Math.Log(n, 2);
  /// <summary>e raised to the power n.</summary>
  public static double Exp(double n) => Math.Exp(n);
  /// <summary>The IEEE 754 remainder a − b·round(a / b) (the quotient rounded to the nearest integer, ties to
  /// even).</summary>
  public static double IEEERemainder(double a, double b) => Math.IEEERemainder(a, b);
  /// <summary>The larger of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static byte Max(byte a, byte b) => Math.Max(a, b);
  /// <summary>The larger of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static sbyte Max(sbyte a, sbyte b) => Math.Max(a, b);
  /// <summary>The larger of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static short Max(short a, short b) => Math.Max(a, b);
  /// <summary>The larger of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static ushort Max(ushort a, ushort b) => Math.Max(a, b);
  /// <summary>The larger of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static decimal Max(decimal a, decimal b) => Math.Max(a, b);
  /// <summary>The larger of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static int Max(int a, int b) => Math.Max(a, b);
  /// <summary>The larger of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static uint Max(uint a, uint b) => Math.Max(a, b);
  /// <summary>The larger of <paramref name="a"/> and <paramref name="b"/> (NaN if either is NaN).</summary>
  public static float Max(float a, float b) => Math.Max(a, b);
  /// <summary>The larger of <paramref name="a"/> and <paramref name="b"/> (NaN if either is NaN).</summary>
  public static double Max(double a, double b) => Math.Max(a, b);
  /// <summary>The larger of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static long Max(long a, long b) => Math.Max(a, b);
  /// <summary>The larger of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static ulong Max(ulong a, ulong b) => Math.Max(a, b);
  /// <summary>The smaller of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static byte Min(byte a, byte b) => Math.Min(a, b);
  /// <summary>The smaller of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static sbyte Min(sbyte a, sbyte b) => Math.Min(a, b);
  /// <summary>The smaller of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static short Min(short a, short b) => Math.Min(a, b);
  /// <summary>The smaller of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static ushort Min(ushort a, ushort b) => Math.Min(a, b);
  /// <summary>The smaller of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static decimal Min(decimal a, decimal b) => Math.Min(a, b);
  /// <summary>The smaller of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static int Min(int a, int b) => Math.Min(a, b);
  /// <summary>The smaller of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static uint Min(uint a, uint b) => Math.Min(a, b);
  /// <summary>The smaller of <paramref name="a"/> and <paramref name="b"/> (NaN if either is NaN).</summary>
  public static float Min(float a, float b) => Math.Min(a, b);
  /// <summary>The smaller of <paramref name="a"/> and <paramref name="b"/> (NaN if either is NaN).</summary>
  public static double Min(double a, double b) => Math.Min(a, b);
  /// <summary>The smaller of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static long Min(long a, long b) => Math.Min(a, b);
  /// <summary>The smaller of <paramref name="a"/> and <paramref name="b"/>.</summary>
  public static ulong Min(ulong a, ulong b) => Math.Min(a, b);
  /// <summary><paramref name="d"/> rounded to <paramref name="digits"/> decimal places, midpoints as
  /// <paramref name="mode"/> says.</summary>
  public static decimal Round(decimal d, int digits, MidpointRounding mode) => Math.Round(d, digits, mode);
  /// <summary><paramref name="d"/> rounded to an integral value, midpoints as <paramref name="mode"/> says.</summary>
  public static decimal Round(decimal d, MidpointRounding mode) => Math.Round(d, mode);
  /// <summary><paramref name="d"/> rounded to <paramref name="digits"/> decimal places, midpoints to even.</summary>
  public static decimal Round(decimal d, int digits) => Math.Round(d, digits);
  /// <summary><paramref name="d"/> rounded to an integral value, midpoints to even.</summary>
  public static decimal Round(decimal d) => Math.Round(d);
  /// <summary><paramref name="d"/> rounded to <paramref name="digits"/> decimal places, midpoints as
  /// <paramref name="mode"/> says.</summary>
  public static double Round(double d, int digits, MidpointRounding mode) => Math.Round(d, digits, mode);
  /// <summary><paramref name="d"/> rounded to an integral value, midpoints as <paramref name="mode"/> says.</summary>
  public static double Round(double d, MidpointRounding mode) => Math.Round(d, mode);
  /// <summary><paramref name="d"/> rounded to <paramref name="digits"/> decimal places, midpoints to even.</summary>
  public static double Round(double d, int digits) => Math.Round(d, digits);
  /// <summary><paramref name="d"/> rounded to an integral value, midpoints to even.</summary>
  public static double Round(double d) => Math.Round(d);
  /// <summary>The sign of <paramref name="d"/>: −1, 0 or 1.</summary>
  public static int Sign(sbyte d) => Math.Sign(d);
  /// <summary>The sign of <paramref name="d"/>: −1, 0 or 1.</summary>
  public static int Sign(short d) => Math.Sign(d);
  /// <summary>The sign of <paramref name="d"/>: −1, 0 or 1.</summary>
  public static int Sign(int d) => Math.Sign(d);
  /// <summary>The sign of <paramref name="d"/>: −1, 0 or 1 (a NaN throws
  /// <see cref="System.ArithmeticException"/>).</summary>
  public static int Sign(float d) => Math.Sign(d);
  /// <summary>The sign of <paramref name="d"/>: −1, 0 or 1.</summary>
  public static int Sign(decimal d) => Math.Sign(d);
  /// <summary>The sign of <paramref name="d"/>: −1, 0 or 1 (a NaN throws
  /// <see cref="System.ArithmeticException"/>).</summary>
  public static int Sign(double d) => Math.Sign(d);
  /// <summary>The sign of <paramref name="d"/>: −1, 0 or 1.</summary>
  public static int Sign(long d) => Math.Sign(d);

  /// <summary>Maps <paramref name="value"/> linearly from [valueMin, valueMax] onto [resultMin, resultMax] (no clamping; the int form divides first, truncating, as OpenTK).</summary>
  public static int MapRange(int value, int valueMin, int valueMax, int resultMin, int resultMax) =>
    resultMin + (resultMax - resultMin) * ((value - valueMin) / (valueMax - valueMin));
  /// <summary>Maps <paramref name="value"/> linearly from [valueMin, valueMax] onto [resultMin, resultMax], without
  /// clamping.</summary>
  public static float MapRange(float value, float valueMin, float valueMax, float resultMin, float resultMax) =>
    resultMin + (resultMax - resultMin) * ((value - valueMin) / (valueMax - valueMin));
  /// <summary>Maps <paramref name="value"/> linearly from [valueMin, valueMax] onto [resultMin, resultMax], without
  /// clamping.</summary>
  public static double MapRange(double value, double valueMin, double valueMax, double resultMin, double resultMax) =>
    resultMin + (resultMax - resultMin) * ((value - valueMin) / (valueMax - valueMin));
}
