using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;

namespace Rendering.Accel;

/// <summary>
/// The boxes of an inner node's two children side by side (lane 0: left, lane 1: right), so one
/// traversal step tests both with the same SIMD slab arithmetic: <see cref="Hit"/> for a ray segment
/// (scene members), <see cref="Cross"/> for a whole line (mesh triangles, whose CSG lists need every hit).
/// </summary>
internal struct BvhChildBoxes
{
  public Vector128<double> MinX, MaxX, MinY, MaxY, MinZ, MaxZ;

  /// <summary>
  /// The two boxes grown by <paramref name="pad"/>. A padded test may keep a box an exact one would drop,
  /// never the reverse, which is all exactness needs when the item tests decide.
  /// </summary>
  public BvhChildBoxes(in BvhNode left, in BvhNode right, double pad = 0.0)
  {
    MinX = Vector128.Create(left.MinX - pad, right.MinX - pad);
    MaxX = Vector128.Create(left.MaxX + pad, right.MaxX + pad);
    MinY = Vector128.Create(left.MinY - pad, right.MinY - pad);
    MaxY = Vector128.Create(left.MaxY + pad, right.MaxY + pad);
    MinZ = Vector128.Create(left.MinZ - pad, right.MinZ - pad);
    MaxZ = Vector128.Create(left.MaxZ + pad, right.MaxZ + pad);
  }

  /// <summary>
  /// Slab test of both boxes against the ray (origin o, inverse direction inv): bit 0 left, bit 1 right is set
  /// when the box overlaps [0, <paramref name="best"/>]; <paramref name="entry"/> gets each box's entry t.
  /// Same answers as <see cref="Slab"/> per box: a NaN in any slab (0 · ∞) means a miss there too.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public readonly int Hit(Vector128<double> ox, Vector128<double> oy, Vector128<double> oz,
                          Vector128<double> ix, Vector128<double> iy, Vector128<double> iz,
                          double best, out Vector128<double> entry)
  {
    Vector128<double> t0 = (MinX - ox) * ix, t1 = (MaxX - ox) * ix;
    // Math.Min/Max propagate NaN, the native min/max do not: track "no NaN" separately.
    Vector128<double> ordered = Vector128.Equals(t0, t0) & Vector128.Equals(t1, t1);
    Vector128<double> tn = Vector128.MinNative(t0, t1), tf = Vector128.MaxNative(t0, t1);
    t0 = (MinY - oy) * iy;
    t1 = (MaxY - oy) * iy;
    ordered &= Vector128.Equals(t0, t0) & Vector128.Equals(t1, t1);
    tn = Vector128.MaxNative(tn, Vector128.MinNative(t0, t1));
    tf = Vector128.MinNative(tf, Vector128.MaxNative(t0, t1));
    t0 = (MinZ - oz) * iz;
    t1 = (MaxZ - oz) * iz;
    ordered &= Vector128.Equals(t0, t0) & Vector128.Equals(t1, t1);
    tn = Vector128.MaxNative(tn, Vector128.MinNative(t0, t1));
    tf = Vector128.MinNative(tf, Vector128.MaxNative(t0, t1));
    entry = tn;
    Vector128<double> hit = ordered & Vector128.LessThanOrEqual(tn, tf) & Vector128.GreaterThanOrEqual(tf, Vector128<double>.Zero) &
                            Vector128.LessThanOrEqual(tn, Vector128.Create(best));
    return (int)hit.ExtractMostSignificantBits();
  }

  /// <summary>
  /// The line o + t·d (inverse direction inv) against both boxes: <paramref name="near"/> and <paramref name="far"/> get
  /// each box's parameter interval; returns a mask (bit 0 left, bit 1 right) of boxes the line crosses. A slab
  /// whose parameters are NaN (d = 0 with the origin exactly on the slab's plane) does not restrict the line.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public readonly int Cross(Vector128<double> ox, Vector128<double> oy, Vector128<double> oz,
                            Vector128<double> ix, Vector128<double> iy, Vector128<double> iz,
                            out Vector128<double> near, out Vector128<double> far)
  {
    Vector128<double> lo = Vector128.Create(double.NegativeInfinity), hi = Vector128.Create(double.PositiveInfinity);
    near = lo;
    far = hi;
    LineSlab(MinX, MaxX, ox, ix, lo, hi, ref near, ref far);
    LineSlab(MinY, MaxY, oy, iy, lo, hi, ref near, ref far);
    LineSlab(MinZ, MaxZ, oz, iz, lo, hi, ref near, ref far);
    return (int)Vector128.LessThanOrEqual(near, far).ExtractMostSignificantBits();
  }

  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  static void LineSlab(Vector128<double> min, Vector128<double> max, Vector128<double> o, Vector128<double> inv,
                       Vector128<double> lo, Vector128<double> hi, ref Vector128<double> near, ref Vector128<double> far)
  {
    Vector128<double> t0 = (min - o) * inv, t1 = (max - o) * inv;
    Vector128<double> ordered = Vector128.Equals(t0, t0) & Vector128.Equals(t1, t1);
    Vector128<double> tn = Vector128.ConditionalSelect(ordered, Vector128.MinNative(t0, t1), lo);
    Vector128<double> tf = Vector128.ConditionalSelect(ordered, Vector128.MaxNative(t0, t1), hi);
    near = Vector128.MaxNative(near, tn);
    far = Vector128.MinNative(far, tf);
  }

  /// <summary>The scalar slab test of one box (the traversal's root, and the reference for <see cref="Hit"/>).</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static bool Slab(in BvhNode n, double ox, double oy, double oz, double ix, double iy, double iz, double best, out double entry)
  {
    double t0 = (n.MinX - ox) * ix, t1 = (n.MaxX - ox) * ix;
    double tn = System.Math.Min(t0, t1), tf = System.Math.Max(t0, t1);
    t0 = (n.MinY - oy) * iy;
    t1 = (n.MaxY - oy) * iy;
    tn = System.Math.Max(tn, System.Math.Min(t0, t1));
    tf = System.Math.Min(tf, System.Math.Max(t0, t1));
    t0 = (n.MinZ - oz) * iz;
    t1 = (n.MaxZ - oz) * iz;
    tn = System.Math.Max(tn, System.Math.Min(t0, t1));
    tf = System.Math.Min(tf, System.Math.Max(t0, t1));
    entry = tn;
    return tn <= tf && tf >= 0.0 && tn <= best;
  }
}
