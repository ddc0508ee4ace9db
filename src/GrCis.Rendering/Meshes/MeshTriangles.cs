using Scene3D;
using System.Collections.Generic;
using System.Runtime.CompilerServices;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// A mesh's triangles as a flat array (9 doubles each: a, b − a, c − a) and the one ray–triangle test
/// (Möller–Trumbore) every mesh query uses, so the BVH and the brute-force search give the same bits.
/// </summary>
internal sealed class MeshTriangles
{
  readonly double[] tri;

  /// <summary>The triangles of <paramref name="mesh"/> in their own order (handle k at 9k).</summary>
  public MeshTriangles(SceneBrep mesh)
  {
    int n = mesh.Triangles;
    tri = new double[9 * n];
    Vector3d min = Vector3d.PositiveInfinity, max = Vector3d.NegativeInfinity;
    for (int i = 0; i < n; i++)
    {
      mesh.GetTriangleVertices(i, out Vector3 pa, out Vector3 pb, out Vector3 pc);
      Vector3d a = pa, b = pb, c = pc;
      Store(tri, 9 * i, a, b, c);
      min = Vector3d.ComponentMin(min, Vector3d.ComponentMin(a, Vector3d.ComponentMin(b, c)));
      max = Vector3d.ComponentMax(max, Vector3d.ComponentMax(a, Vector3d.ComponentMax(b, c)));
    }
    // The diagonal of the triangles' box: the same value as the BVH's root box gives.
    Extent = n > 0 ? new Vector3d(max.X - min.X, max.Y - min.Y, max.Z - min.Z).Length : 0.0;
  }

  public int Count => tri.Length / 9;

  /// <summary>Size of the mesh's box (for relative tolerances), as <see cref="MeshBvh.Extent"/>.</summary>
  public double Extent { get; }

  /// <summary>
  /// Appends every hit of the line <c>p0 + t p1</c> (any t), testing each triangle in turn: the search
  /// GrCis did, kept for the faithful path (<see cref="Accel.AccelMode.None"/>).
  /// </summary>
  public void IntersectAll(in Vector3d p0, in Vector3d p1, List<MeshHit> hits)
  {
    double ox = p0.X, oy = p0.Y, oz = p0.Z, dx = p1.X, dy = p1.Y, dz = p1.Z;
    int n = Count;
    for (int k = 0; k < n; k++)
      if (Hit(tri, 9 * k, ox, oy, oz, dx, dy, dz, out double t, out double u, out double v, out bool front))
        hits.Add(new MeshHit { T = t, Triangle = k, U = u, V = v, Front = front });
  }

  /// <summary>Writes a triangle at <paramref name="o"/>: the first vertex and the two edges from it.</summary>
  public static void Store(double[] tri, int o, in Vector3d a, in Vector3d b, in Vector3d c)
  {
    Vector3d e1 = b - a, e2 = c - a;
    tri[o] = a.X; tri[o + 1] = a.Y; tri[o + 2] = a.Z;
    tri[o + 3] = e1.X; tri[o + 4] = e1.Y; tri[o + 5] = e1.Z;
    tri[o + 6] = e2.X; tri[o + 7] = e2.Y; tri[o + 8] = e2.Z;
  }

  /// <summary>Möller–Trumbore against the triangle stored at <paramref name="o"/>.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static bool Hit(double[] tri, int o, double ox, double oy, double oz, double dx, double dy, double dz,
                         out double t, out double u, out double v, out bool front)
  {
    double e1x = tri[o + 3], e1y = tri[o + 4], e1z = tri[o + 5];
    double e2x = tri[o + 6], e2y = tri[o + 7], e2z = tri[o + 8];
    t = u = v = 0.0;
    front = false;

    // pvec = d × e2, det = e1 · pvec.
    double px = dy * e2z - dz * e2y, py = dz * e2x - dx * e2z, pz = dx * e2y - dy * e2x;
    double det = e1x * px + e1y * py + e1z * pz;
    if (det == 0.0)
      return false;
    double inv = 1.0 / det;
    double tx = ox - tri[o], ty = oy - tri[o + 1], tz = oz - tri[o + 2];
    u = (tx * px + ty * py + tz * pz) * inv;
    if (u < 0.0 || u > 1.0)
      return false;
    double qx = ty * e1z - tz * e1y, qy = tz * e1x - tx * e1z, qz = tx * e1y - ty * e1x;
    v = (dx * qx + dy * qy + dz * qz) * inv;
    if (v < 0.0 || u + v > 1.0)
      return false;
    t = (e2x * qx + e2y * qy + e2z * qz) * inv;
    front = det > 0.0;
    return true;
  }
}
