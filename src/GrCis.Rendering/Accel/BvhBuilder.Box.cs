using System;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;

namespace Rendering.Accel;

internal sealed partial class BvhBuilder
{
  /// <summary>
  /// The arithmetic of box unions and bin numbers, chosen once per build (T is a struct: no call per use). Both
  /// implementations give the same answers on the inputs <see cref="Native"/> is chosen for.
  /// </summary>
  interface IBinning
  {
    static abstract Vector256<double> Min(Vector256<double> a, Vector256<double> b);

    static abstract Vector256<double> Max(Vector256<double> a, Vector256<double> b);

    /// <summary>Bin of each axis for t = (centre − cmin) · bins / extent (t ≥ 0 or NaN): min(bins − 1, (int)t), bins − 1 in every lane of <paramref name="last"/>.</summary>
    static abstract void Bins(Vector256<double> t, Vector256<double> last, out int x, out int y, out int z);
  }

  /// <summary>As <see cref="Math.Min(double, double)"/>: NaN wins, −0 is below +0 (as <see cref="Aabb"/> unions).</summary>
  readonly struct Exact : IBinning
  {
    public static Vector256<double> Min(Vector256<double> a, Vector256<double> b) => Vector256.Min(a, b);

    public static Vector256<double> Max(Vector256<double> a, Vector256<double> b) => Vector256.Max(a, b);

    public static void Bins(Vector256<double> t, Vector256<double> last, out int x, out int y, out int z)
    {
      int top = (int)last.GetElement(0);
      x = Math.Min(top, (int)t.GetElement(0));
      y = Math.Min(top, (int)t.GetElement(1));
      z = Math.Min(top, (int)t.GetElement(2));
    }
  }

  /// <summary>
  /// The native min and max (one instruction each), with the sign of a zero tie fixed the way IEEE's minimum and maximum
  /// fix it (on x86 a tie returns the second operand): the same answers as <see cref="Exact"/> when no input is NaN.
  /// </summary>
  readonly struct Native : IBinning
  {
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector256<double> Min(Vector256<double> a, Vector256<double> b) =>
      Vector256.MinNative(a, b) | (Vector256.Equals(a, b) & a);   // a tie: −0 if either is −0

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector256<double> Max(Vector256<double> a, Vector256<double> b) =>
      Vector256.MaxNative(a, b) & ~Vector256.AndNot(Vector256.Equals(a, b), a);   // a tie: +0 if either is +0

    /// <summary>
    /// All three at once: NaN to 0 and (int) of t ≥ 0 is its floor, as the scalar conversion does; floor(t) ≤ bins − 1
    /// plus 2^52 holds the bin in its low mantissa bits.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Bins(Vector256<double> t, Vector256<double> last, out int x, out int y, out int z)
    {
      t = Vector256.ConditionalSelect(Vector256.Equals(t, t), t, Vector256<double>.Zero);
      Vector256<long> bits = (Vector256.MinNative(Vector256.Floor(t), last) +
                              Vector256.Create(4503599627370496.0)).AsInt64();
      x = (int)bits.GetElement(0);
      y = (int)bits.GetElement(1);
      z = (int)bits.GetElement(2);
    }
  }

  /// <summary>An item in build order: box and centroid as (x, y, z, 0).</summary>
  struct Item
  {
    public Vector256<double> Min, Max, Center;
  }

  /// <summary>A box as (x, y, z, ·) vectors; min and max as <see cref="Math.Min(double, double)"/> (NaN and −0 alike), so a union is that of <see cref="Aabb"/>.</summary>
  struct Box
  {
    public Vector256<double> Min, Max;

    public static readonly Box Empty = new()
    {
      Min = Vector256.Create(double.PositiveInfinity),
      Max = Vector256.Create(double.NegativeInfinity),
    };

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void Add<T>(Vector256<double> min, Vector256<double> max) where T : struct, IBinning
    {
      Min = T.Min(Min, min);
      Max = T.Max(Max, max);
    }

    /// <summary>As <see cref="Aabb.HalfArea"/>, to the last bit.</summary>
    public readonly double HalfArea
    {
      [MethodImpl(MethodImplOptions.AggressiveInlining)]
      get
      {
        double x0 = Min.GetElement(0), y0 = Min.GetElement(1), z0 = Min.GetElement(2);
        double x1 = Max.GetElement(0), y1 = Max.GetElement(1), z1 = Max.GetElement(2);
        if (x0 > x1 || y0 > y1 || z0 > z1)
          return 0.0;
        double dx = x1 - x0, dy = y1 - y0, dz = z1 - z0;
        return dx * dy + dy * dz + dz * dx;
      }
    }
  }
}
