using System;

namespace OpenTK.Mathematics;

// OpenTK 4's MathHelper also forwards System.Math's functions, so OpenTK code can call them there; plus MapRange.
public static partial class MathHelper
{
  public static decimal Abs(decimal n) => Math.Abs(n);
  public static double Abs(double n) => Math.Abs(n);
  public static short Abs(short n) => Math.Abs(n);
  public static int Abs(int n) => Math.Abs(n);
  public static long Abs(long n) => Math.Abs(n);
  public static sbyte Abs(sbyte n) => Math.Abs(n);
  public static float Abs(float n) => Math.Abs(n);
  public static double Sin(double radians) => Math.Sin(radians);
  public static double Sinh(double radians) => Math.Sinh(radians);
  public static double Asin(double radians) => Math.Asin(radians);
  public static double Cos(double radians) => Math.Cos(radians);
  public static double Cosh(double radians) => Math.Cosh(radians);
  public static double Acos(double radians) => Math.Acos(radians);
  public static double Tan(double radians) => Math.Tan(radians);
  public static double Tanh(double radians) => Math.Tanh(radians);
  public static double Atan(double radians) => Math.Atan(radians);
  public static double Atan2(double y, double x) => Math.Atan2(y, x);
  public static long BigMul(int a, int b) => Math.BigMul(a, b);
  public static double Sqrt(double n) => Math.Sqrt(n);
  public static double Pow(double x, double y) => Math.Pow(x, y);
  public static decimal Ceiling(decimal n) => Math.Ceiling(n);
  public static double Ceiling(double n) => Math.Ceiling(n);
  public static decimal Floor(decimal n) => Math.Floor(n);
  public static double Floor(double n) => Math.Floor(n);
  public static decimal Truncate(decimal n) => Math.Truncate(n);
  public static double Truncate(double n) => Math.Truncate(n);
  public static double Log(double n) => Math.Log(n);
  public static double Log(double n, double newBase) => Math.Log(n, newBase);
  public static double Log10(double n) => Math.Log10(n);
  public static double Log2(double n) => Math.Log(n, 2);
  public static double Exp(double n) => Math.Exp(n);
  public static double IEEERemainder(double a, double b) => Math.IEEERemainder(a, b);
  public static byte Max(byte a, byte b) => Math.Max(a, b);
  public static sbyte Max(sbyte a, sbyte b) => Math.Max(a, b);
  public static short Max(short a, short b) => Math.Max(a, b);
  public static ushort Max(ushort a, ushort b) => Math.Max(a, b);
  public static decimal Max(decimal a, decimal b) => Math.Max(a, b);
  public static int Max(int a, int b) => Math.Max(a, b);
  public static uint Max(uint a, uint b) => Math.Max(a, b);
  public static float Max(float a, float b) => Math.Max(a, b);
  public static double Max(double a, double b) => Math.Max(a, b);
  public static long Max(long a, long b) => Math.Max(a, b);
  public static ulong Max(ulong a, ulong b) => Math.Max(a, b);
  public static byte Min(byte a, byte b) => Math.Min(a, b);
  public static sbyte Min(sbyte a, sbyte b) => Math.Min(a, b);
  public static short Min(short a, short b) => Math.Min(a, b);
  public static ushort Min(ushort a, ushort b) => Math.Min(a, b);
  public static decimal Min(decimal a, decimal b) => Math.Min(a, b);
  public static int Min(int a, int b) => Math.Min(a, b);
  public static uint Min(uint a, uint b) => Math.Min(a, b);
  public static float Min(float a, float b) => Math.Min(a, b);
  public static double Min(double a, double b) => Math.Min(a, b);
  public static long Min(long a, long b) => Math.Min(a, b);
  public static ulong Min(ulong a, ulong b) => Math.Min(a, b);
  public static decimal Round(decimal d, int digits, MidpointRounding mode) => Math.Round(d, digits, mode);
  public static decimal Round(decimal d, MidpointRounding mode) => Math.Round(d, mode);
  public static decimal Round(decimal d, int digits) => Math.Round(d, digits);
  public static decimal Round(decimal d) => Math.Round(d);
  public static double Round(double d, int digits, MidpointRounding mode) => Math.Round(d, digits, mode);
  public static double Round(double d, MidpointRounding mode) => Math.Round(d, mode);
  public static double Round(double d, int digits) => Math.Round(d, digits);
  public static double Round(double d) => Math.Round(d);
  public static int Sign(sbyte d) => Math.Sign(d);
  public static int Sign(short d) => Math.Sign(d);
  public static int Sign(int d) => Math.Sign(d);
  public static int Sign(float d) => Math.Sign(d);
  public static int Sign(decimal d) => Math.Sign(d);
  public static int Sign(double d) => Math.Sign(d);
  public static int Sign(long d) => Math.Sign(d);

  /// <summary>Maps <paramref name="value"/> linearly from [valueMin, valueMax] onto [resultMin, resultMax] (no clamping; the int form divides first, truncating, as OpenTK).</summary>
  public static int MapRange(int value, int valueMin, int valueMax, int resultMin, int resultMax) =>
    resultMin + (resultMax - resultMin) * ((value - valueMin) / (valueMax - valueMin));
  public static float MapRange(float value, float valueMin, float valueMax, float resultMin, float resultMax) =>
    resultMin + (resultMax - resultMin) * ((value - valueMin) / (valueMax - valueMin));
  public static double MapRange(double value, double valueMin, double valueMax, double resultMin, double resultMax) =>
    resultMin + (resultMax - resultMin) * ((value - valueMin) / (valueMax - valueMin));
}
