using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// Four triangles of a mesh leaf side by side (lane l of each vector is triangle l; a, b − a, c − a as in
/// <see cref="MeshTriangles"/>), tested together by <see cref="Hit"/>. Unused lanes are all zero: their determinant is
/// zero, so they never hit.
/// </summary>
internal struct TriangleBlock
{
  /// <summary>Triangles per block.</summary>
  public const int Width = 4;

  public Vector256<double> Ax, Ay, Az, E1x, E1y, E1z, E2x, E2y, E2z;

  /// <summary>Writes a triangle into lane <paramref name="lane"/> (the same doubles <see cref="MeshTriangles.Store"/> writes).</summary>
  public void Set(int lane, in Vector3d a, in Vector3d b, in Vector3d c)
  {
    Vector3d e1 = b - a, e2 = c - a;
    Lane(ref Ax, lane) = a.X; Lane(ref Ay, lane) = a.Y; Lane(ref Az, lane) = a.Z;
    Lane(ref E1x, lane) = e1.X; Lane(ref E1y, lane) = e1.Y; Lane(ref E1z, lane) = e1.Z;
    Lane(ref E2x, lane) = e2.X; Lane(ref E2y, lane) = e2.Y; Lane(ref E2z, lane) = e2.Z;
  }

  static ref double Lane(ref Vector256<double> v, int lane) => ref Unsafe.Add(ref Unsafe.As<Vector256<double>, double>(ref v), lane);

  /// <summary>
  /// Möller–Trumbore against the four triangles: bit l set when triangle l is hit, with its t, u, v and determinant
  /// (front: det &gt; 0) in lane l. Per lane the operations, their order and their rounding are those of
  /// <see cref="MeshTriangles.Hit"/> (products and sums, no fused multiply–add), so a hit has the same bits, and the
  /// same comparisons reject a lane (a NaN u or v passes them there, and so here).
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public readonly int Hit(Vector256<double> ox, Vector256<double> oy, Vector256<double> oz,
                          Vector256<double> dx, Vector256<double> dy, Vector256<double> dz,
                          out Vector256<double> t, out Vector256<double> u, out Vector256<double> v, out Vector256<double> det)
  {
    Vector256<double> px = dy * E2z - dz * E2y, py = dz * E2x - dx * E2z, pz = dx * E2y - dy * E2x;
    det = E1x * px + E1y * py + E1z * pz;
    Vector256<double> inv = Vector256<double>.One / det;
    Vector256<double> tx = ox - Ax, ty = oy - Ay, tz = oz - Az;
    u = (tx * px + ty * py + tz * pz) * inv;
    Vector256<double> qx = ty * E1z - tz * E1y, qy = tz * E1x - tx * E1z, qz = tx * E1y - ty * E1x;
    v = (dx * qx + dy * qy + dz * qz) * inv;
    t = (E2x * qx + E2y * qy + E2z * qz) * inv;
    Vector256<double> zero = Vector256<double>.Zero, one = Vector256<double>.One;
    Vector256<double> miss = Vector256.Equals(det, zero) | Vector256.LessThan(u, zero) | Vector256.GreaterThan(u, one) |
                             Vector256.LessThan(v, zero) | Vector256.GreaterThan(u + v, one);
    return (int)(~miss).ExtractMostSignificantBits();
  }
}
