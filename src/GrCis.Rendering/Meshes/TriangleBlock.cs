using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// Four triangles of a mesh leaf side by side (lane l of each vector is triangle l), tested together by <see cref="Hit"/>:
/// the vertices a, b, c as the mesh's floats (144 bytes, half the doubles of a, b − a, c − a) and each lane's original
/// triangle handle, so a block is three cache lines and a hit needs no other array. Unused lanes are all zero (handle −1):
/// their determinant is zero, so they never hit.
/// </summary>
internal struct TriangleBlock
{
  /// <summary>Triangles per block.</summary>
  public const int Width = 4;

  public Vector128<float> Ax, Ay, Az, Bx, By, Bz, Cx, Cy, Cz;

  /// <summary>The original triangle handle of each lane (−1 in an unused lane).</summary>
  public Lanes Id;

  /// <summary>Four ints, one per lane.</summary>
  [InlineArray(Width)]
  public struct Lanes
  {
    int lane;
  }

  /// <summary>Every lane unused: zero vertices, handle −1.</summary>
  public void Clear()
  {
    this = default;
    for (int lane = 0; lane < Width; lane++)
      Id[lane] = -1;
  }

  /// <summary>Writes triangle <paramref name="id"/> into lane <paramref name="lane"/>.</summary>
  public void Set(int lane, int id, in Vector3 a, in Vector3 b, in Vector3 c)
  {
    Lane(ref Ax, lane) = a.X; Lane(ref Ay, lane) = a.Y; Lane(ref Az, lane) = a.Z;
    Lane(ref Bx, lane) = b.X; Lane(ref By, lane) = b.Y; Lane(ref Bz, lane) = b.Z;
    Lane(ref Cx, lane) = c.X; Lane(ref Cy, lane) = c.Y; Lane(ref Cz, lane) = c.Z;
    Id[lane] = id;
  }

  static ref float Lane(ref Vector128<float> v, int lane) => ref Unsafe.Add(ref Unsafe.As<Vector128<float>, float>(ref v), lane);

  /// <summary>
  /// Möller–Trumbore against the four triangles: bit l set when triangle l is hit, with its t, u, v and determinant
  /// (front: det &gt; 0) in lane l. The edges are b − a and c − a of the vertices widened to doubles, the doubles
  /// <see cref="MeshTriangles.Store"/> keeps; from there, per lane, the operations, their order and their rounding are
  /// those of <see cref="MeshTriangles.Hit"/> (products and sums, no fused multiply–add), so a hit has the same bits, and
  /// the same comparisons reject a lane (a NaN u or v passes them there, and so here).
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public readonly int Hit(Vector256<double> ox, Vector256<double> oy, Vector256<double> oz,
                          Vector256<double> dx, Vector256<double> dy, Vector256<double> dz,
                          out Vector256<double> t, out Vector256<double> u, out Vector256<double> v, out Vector256<double> det)
  {
    Vector256<double> ax = MeshNode.Widen(Ax), ay = MeshNode.Widen(Ay), az = MeshNode.Widen(Az);
    Vector256<double> e1x = MeshNode.Widen(Bx) - ax, e1y = MeshNode.Widen(By) - ay, e1z = MeshNode.Widen(Bz) - az;
    Vector256<double> e2x = MeshNode.Widen(Cx) - ax, e2y = MeshNode.Widen(Cy) - ay, e2z = MeshNode.Widen(Cz) - az;
    Vector256<double> px = dy * e2z - dz * e2y, py = dz * e2x - dx * e2z, pz = dx * e2y - dy * e2x;
    det = e1x * px + e1y * py + e1z * pz;
    Vector256<double> inv = Vector256<double>.One / det;
    Vector256<double> tx = ox - ax, ty = oy - ay, tz = oz - az;
    u = (tx * px + ty * py + tz * pz) * inv;
    Vector256<double> qx = ty * e1z - tz * e1y, qy = tz * e1x - tx * e1z, qz = tx * e1y - ty * e1x;
    v = (dx * qx + dy * qy + dz * qz) * inv;
    t = (e2x * qx + e2y * qy + e2z * qz) * inv;
    Vector256<double> zero = Vector256<double>.Zero, one = Vector256<double>.One;
    Vector256<double> miss = Vector256.Equals(det, zero) | Vector256.LessThan(u, zero) | Vector256.GreaterThan(u, one) |
                             Vector256.LessThan(v, zero) | Vector256.GreaterThan(u + v, one);
    return (int)(~miss).ExtractMostSignificantBits();
  }
}
