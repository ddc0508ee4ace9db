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
  /// The line o + t·d (inverse direction inv) against the four boxes: <paramref name="near"/> and <paramref name="far"/> get
  /// each box's parameter interval; returns a mask of the boxes the line crosses. A slab whose parameters are NaN
  /// (d = 0 with the origin exactly on the slab's plane) does not restrict the line. <paramref name="noNaN"/>: the caller
  /// knows no parameter can be NaN (<see cref="NoNaN"/>, finite boxes), so the cheaper <see cref="CrossFinite"/> answers,
  /// the same to the bit.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public readonly int Cross(Vector256<double> ox, Vector256<double> oy, Vector256<double> oz,
                            Vector256<double> ix, Vector256<double> iy, Vector256<double> iz, bool noNaN,
                            out Vector256<double> near, out Vector256<double> far)
  {
    if (noNaN)
      return CrossFinite(ox, oy, oz, ix, iy, iz, out near, out far);
    Vector256<double> lo = Vector256.Create(double.NegativeInfinity), hi = Vector256.Create(double.PositiveInfinity);
    near = lo;
    far = hi;
    LineSlab(MinX, MaxX, ox, ix, lo, hi, ref near, ref far);
    LineSlab(MinY, MaxY, oy, iy, lo, hi, ref near, ref far);
    LineSlab(MinZ, MaxZ, oz, iz, lo, hi, ref near, ref far);
    return (int)Vector256.LessThanOrEqual(near, far).ExtractMostSignificantBits() & Valid;
  }

  /// <summary>
  /// <see cref="Cross"/> for a line whose origin and inverse direction are finite and whose inverse direction has no zero
  /// component (<see cref="NoNaN"/>), against finite boxes: no slab parameter can then be NaN, so the NaN lanes' selection is left out and every
  /// answer is <see cref="Cross"/>'s, bit for bit.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  readonly int CrossFinite(Vector256<double> ox, Vector256<double> oy, Vector256<double> oz,
                           Vector256<double> ix, Vector256<double> iy, Vector256<double> iz,
                           out Vector256<double> near, out Vector256<double> far)
  {
    Vector256<double> t0 = (MinX - ox) * ix, t1 = (MaxX - ox) * ix;
    near = Vector256.MinNative(t0, t1);
    far = Vector256.MaxNative(t0, t1);
    t0 = (MinY - oy) * iy;
    t1 = (MaxY - oy) * iy;
    near = Vector256.MaxNative(near, Vector256.MinNative(t0, t1));
    far = Vector256.MinNative(far, Vector256.MaxNative(t0, t1));
    t0 = (MinZ - oz) * iz;
    t1 = (MaxZ - oz) * iz;
    near = Vector256.MaxNative(near, Vector256.MinNative(t0, t1));
    far = Vector256.MinNative(far, Vector256.MaxNative(t0, t1));
    return (int)Vector256.LessThanOrEqual(near, far).ExtractMostSignificantBits() & Valid;
  }

  /// <summary>
  /// True when (box − o) · inv cannot be NaN for any finite box: o and inv finite, no inverse component zero (an infinite
  /// direction component). Then, in a tree of finite boxes (<see cref="WideBvh.FiniteBoxes"/>), <see cref="Cross"/> may
  /// be told so.
  /// </summary>
  public static bool NoNaN(double ox, double oy, double oz, double ix, double iy, double iz) =>
    double.IsFinite(ox) && double.IsFinite(oy) && double.IsFinite(oz) &&
    double.IsFinite(ix) && double.IsFinite(iy) && double.IsFinite(iz) && ix != 0.0 && iy != 0.0 && iz != 0.0;

  /// <summary>
  /// One axis of <see cref="Cross"/>: narrows [near, far] by the slab [min, max]; a NaN parameter leaves the lane as it is
  /// (also the mesh tree's double fallback, <see cref="Rendering.DoubleStep"/>).
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  internal static void LineSlab(Vector256<double> min, Vector256<double> max, Vector256<double> o, Vector256<double> inv,
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
