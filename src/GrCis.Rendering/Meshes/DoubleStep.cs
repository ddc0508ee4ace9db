using System.Runtime.Intrinsics;
using Rendering.Accel;

namespace Rendering;

/// <summary>
/// The eight-box step in doubles, for a ray <see cref="FloatStep"/> cannot bound (decided once per ray): the double slab
/// test of <see cref="WideNode.Cross"/> (NaN slabs do not restrict the line) on the float boxes widened exactly, four lanes
/// at a time. The float box contains the double box and the double arithmetic is monotone, so the intervals contain the
/// ones of the double boxes; they are rounded outward to floats (near down, far up).
/// </summary>
internal readonly struct DoubleStep(in MeshLine line) : IMeshBoxStep
{
  readonly Vector256<double> ox = Vector256.Create(line.Ox), oy = Vector256.Create(line.Oy), oz = Vector256.Create(line.Oz);
  readonly Vector256<double> ix = Vector256.Create(line.Ix), iy = Vector256.Create(line.Iy), iz = Vector256.Create(line.Iz);

  public int Cross(ref readonly MeshNode n, out Vector256<float> near, out Vector256<float> far)
  {
    var (minXl, minXh) = Vector256.Widen(n.MinX);
    var (minYl, minYh) = Vector256.Widen(n.MinY);
    var (minZl, minZh) = Vector256.Widen(n.MinZ);
    var (maxXl, maxXh) = Vector256.Widen(n.MaxX);
    var (maxYl, maxYh) = Vector256.Widen(n.MaxY);
    var (maxZl, maxZh) = Vector256.Widen(n.MaxZ);
    int mask = WideNode.Cross(minXl, maxXl, minYl, maxYl, minZl, maxZl, ox, oy, oz, ix, iy, iz, out Vector256<double> nearL, out Vector256<double> farL) |
               WideNode.Cross(minXh, maxXh, minYh, maxYh, minZh, maxZh, ox, oy, oz, ix, iy, iz, out Vector256<double> nearH, out Vector256<double> farH) << 4;
    // Used lanes only (an unused one has min +∞ > max −∞; a NaN-free line could otherwise cross it).
    mask &= (int)Vector256.LessThanOrEqual(n.MinX, n.MaxX).ExtractMostSignificantBits();
    Vector256<float> lo = default, hi = default;
    for (int lane = 0; lane < 4; lane++)
    {
      lo = lo.WithElement(lane, MeshNode.Down(nearL.GetElement(lane))).WithElement(lane + 4, MeshNode.Down(nearH.GetElement(lane)));
      hi = hi.WithElement(lane, MeshNode.Up(farL.GetElement(lane))).WithElement(lane + 4, MeshNode.Up(farH.GetElement(lane)));
    }
    near = lo;
    far = hi;
    return mask;
  }
}
