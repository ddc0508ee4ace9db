using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;

namespace Rendering.Accel;

/// <summary>
/// One node of a <see cref="WideBvh"/>: up to four child boxes side by side (lane l of each vector is child l), so
/// one traversal step tests all four with the same SIMD slab arithmetic (<see cref="Vector256{T}"/> of doubles: the
/// per-box arithmetic, and so every answer, is that of the scalar test <see cref="Slab"/>). Lane l is an inner child
/// (<see cref="Count"/>[l] == 0, node <see cref="Index"/>[l]) or a leaf (items <see cref="Index"/>[l] … + Count[l] − 1);
/// lanes not in <see cref="Valid"/> are unused.
/// </summary>
internal struct WideNode
{
  public const int Width = 4;

  public Vector256<double> MinX, MaxX, MinY, MaxY, MinZ, MaxZ;
  public Lanes Index, Count;

  /// <summary>Bit l set: lane l holds a child.</summary>
  public int Valid;

  /// <summary>Four ints, one per lane.</summary>
  [InlineArray(Width)]
  public struct Lanes
  {
    int lane;
  }

  /// <summary>Puts a box in lane <paramref name="lane"/>, grown by <paramref name="pad"/> (see <see cref="WideBvh"/>).</summary>
  public void SetBox(int lane, in BvhNode box, double pad)
  {
    MinX = MinX.WithElement(lane, box.MinX - pad);
    MaxX = MaxX.WithElement(lane, box.MaxX + pad);
    MinY = MinY.WithElement(lane, box.MinY - pad);
    MaxY = MaxY.WithElement(lane, box.MaxY + pad);
    MinZ = MinZ.WithElement(lane, box.MinZ - pad);
    MaxZ = MaxZ.WithElement(lane, box.MaxZ + pad);
    Valid |= 1 << lane;
  }

  /// <summary>
  /// Slab test of the four boxes against the ray (origin o, inverse direction inv): bit l is set when box l overlaps
  /// [0, <paramref name="best"/>]; <paramref name="entry"/> gets each box's entry t. Per box the same answer and entry as
  /// <see cref="Slab"/>: a NaN in any slab (0 · ∞) means a miss there too.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public readonly int Hit(Vector256<double> ox, Vector256<double> oy, Vector256<double> oz,
                          Vector256<double> ix, Vector256<double> iy, Vector256<double> iz,
                          double best, out Vector256<double> entry)
  {
    Vector256<double> t0 = (MinX - ox) * ix, t1 = (MaxX - ox) * ix;
    // Math.Min/Max propagate NaN, the native min/max do not: track "no NaN" separately.
    Vector256<double> ordered = Vector256.Equals(t0, t0) & Vector256.Equals(t1, t1);
    Vector256<double> tn = Vector256.MinNative(t0, t1), tf = Vector256.MaxNative(t0, t1);
    t0 = (MinY - oy) * iy;
    t1 = (MaxY - oy) * iy;
    ordered &= Vector256.Equals(t0, t0) & Vector256.Equals(t1, t1);
    tn = Vector256.MaxNative(tn, Vector256.MinNative(t0, t1));
    tf = Vector256.MinNative(tf, Vector256.MaxNative(t0, t1));
    t0 = (MinZ - oz) * iz;
    t1 = (MaxZ - oz) * iz;
    ordered &= Vector256.Equals(t0, t0) & Vector256.Equals(t1, t1);
    tn = Vector256.MaxNative(tn, Vector256.MinNative(t0, t1));
    tf = Vector256.MinNative(tf, Vector256.MaxNative(t0, t1));
    entry = tn;
    Vector256<double> hit = ordered & Vector256.LessThanOrEqual(tn, tf) & Vector256.GreaterThanOrEqual(tf, Vector256<double>.Zero) &
                            Vector256.LessThanOrEqual(tn, Vector256.Create(best));
    return (int)hit.ExtractMostSignificantBits() & Valid;
  }

  /// <summary>
  /// The line o + t·d (inverse direction inv) against up to four boxes given by their slabs (lane l of each vector is box l):
  /// <paramref name="near"/> and <paramref name="far"/> get each box's parameter interval; returns a mask of the boxes the
  /// line crosses (near ≤ far; the caller masks unused lanes). A slab whose parameters are NaN (d = 0 with the origin
  /// exactly on the slab's plane) does not restrict the line. The mesh tree's double fallback
  /// (<see cref="Rendering.DoubleStep"/>) runs it on its float boxes widened, four at a time.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static int Cross(Vector256<double> minX, Vector256<double> maxX, Vector256<double> minY, Vector256<double> maxY,
                          Vector256<double> minZ, Vector256<double> maxZ,
                          Vector256<double> ox, Vector256<double> oy, Vector256<double> oz,
                          Vector256<double> ix, Vector256<double> iy, Vector256<double> iz,
                          out Vector256<double> near, out Vector256<double> far)
  {
    Vector256<double> lo = Vector256.Create(double.NegativeInfinity), hi = Vector256.Create(double.PositiveInfinity);
    near = lo;
    far = hi;
    LineSlab(minX, maxX, ox, ix, lo, hi, ref near, ref far);
    LineSlab(minY, maxY, oy, iy, lo, hi, ref near, ref far);
    LineSlab(minZ, maxZ, oz, iz, lo, hi, ref near, ref far);
    return (int)Vector256.LessThanOrEqual(near, far).ExtractMostSignificantBits();
  }

  /// <summary>
  /// One axis of <see cref="Cross"/>: narrows [near, far] by the slab [min, max]; a NaN parameter leaves the lane as it is.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  static void LineSlab(Vector256<double> min, Vector256<double> max, Vector256<double> o, Vector256<double> inv,
                       Vector256<double> lo, Vector256<double> hi, ref Vector256<double> near, ref Vector256<double> far)
  {
    Vector256<double> t0 = (min - o) * inv, t1 = (max - o) * inv;
    Vector256<double> ordered = Vector256.Equals(t0, t0) & Vector256.Equals(t1, t1);
    Vector256<double> tn = Vector256.ConditionalSelect(ordered, Vector256.MinNative(t0, t1), lo);
    Vector256<double> tf = Vector256.ConditionalSelect(ordered, Vector256.MaxNative(t0, t1), hi);
    near = Vector256.MaxNative(near, tn);
    far = Vector256.MinNative(far, tf);
  }

  /// <summary>The scalar slab test of one box: the reference <see cref="Hit"/> answers as, lane by lane.</summary>
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
