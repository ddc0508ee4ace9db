using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;

namespace Rendering;

/// <summary>
/// An inner mesh-BVH node's two child boxes side by side (lane 0: left, lane 1: right), slightly padded,
/// so one SIMD slab test answers for both. The test is conservative — it may keep a box an exact test would
/// drop, never the reverse — which is all exactness needs: the triangle tests decide, and every triangle
/// hit lies in its padded leaf box and in all its ancestors'.
/// </summary>
internal struct MeshChildBoxes
{
  public Vector128<double> MinX, MaxX, MinY, MaxY, MinZ, MaxZ;

  /// <summary>Boxes at <paramref name="left"/> and left + 1 in the six-per-node array, grown by <paramref name="pad"/>.</summary>
  public MeshChildBoxes(double[] boxes, int left, double pad)
  {
    int a = 6 * left, b = a + 6;
    MinX = Vector128.Create(boxes[a] - pad, boxes[b] - pad);
    MinY = Vector128.Create(boxes[a + 1] - pad, boxes[b + 1] - pad);
    MinZ = Vector128.Create(boxes[a + 2] - pad, boxes[b + 2] - pad);
    MaxX = Vector128.Create(boxes[a + 3] + pad, boxes[b + 3] + pad);
    MaxY = Vector128.Create(boxes[a + 4] + pad, boxes[b + 4] + pad);
    MaxZ = Vector128.Create(boxes[a + 5] + pad, boxes[b + 5] + pad);
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
    Axis(MinX, MaxX, ox, ix, lo, hi, ref near, ref far);
    Axis(MinY, MaxY, oy, iy, lo, hi, ref near, ref far);
    Axis(MinZ, MaxZ, oz, iz, lo, hi, ref near, ref far);
    return (int)Vector128.LessThanOrEqual(near, far).ExtractMostSignificantBits();
  }

  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  static void Axis(Vector128<double> min, Vector128<double> max, Vector128<double> o, Vector128<double> inv,
                   Vector128<double> lo, Vector128<double> hi, ref Vector128<double> near, ref Vector128<double> far)
  {
    Vector128<double> t0 = (min - o) * inv, t1 = (max - o) * inv;
    Vector128<double> ordered = Vector128.Equals(t0, t0) & Vector128.Equals(t1, t1);
    Vector128<double> tn = Vector128.ConditionalSelect(ordered, Vector128.MinNative(t0, t1), lo);
    Vector128<double> tf = Vector128.ConditionalSelect(ordered, Vector128.MaxNative(t0, t1), hi);
    near = Vector128.MaxNative(near, tn);
    far = Vector128.MinNative(far, tf);
  }
}
