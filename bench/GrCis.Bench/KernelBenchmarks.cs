using System.Collections.Generic;
using BenchmarkDotNet.Attributes;
using GrCis.Testing;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;

namespace GrCis.Bench;

/// <summary>Single ray–solid tests: the allocation-free kernel against GrCis's LinkedList API.</summary>
[MemoryDiagnoser]
public class KernelBenchmarks
{
  readonly Sphere sphere = new();
  readonly Cube cube = new();
  readonly TriangleMesh torus = new(ProceduralMesh.Torus(100, 50));
  Vector3d m0 = new(0.05, 0.02, 5), m1 = new Vector3d(0.3, 0.01, -1).Normalized();
  Vector3d p0 = new(0.1, 0.2, -5), p1 = new Vector3d(0.01, 0.02, 1).Normalized();
  Vector3d c0 = new(0.3, 0.4, -5), c1 = new Vector3d(0.01, 0.02, 1).Normalized();
  Vector3d a = new(-1, -1, 0), b = new(1, -1, 0.2), c = new(0, 1, 0.1);

  [Benchmark]
  public double RaySphere_fast()
  {
    sphere.IntersectFirst(p0, p1, 1.0, out SolidRecord h, out _);
    return h.T;
  }

  [Benchmark]
  public double RaySphere_linkedlist()
  {
    LinkedList<Intersection>? list = sphere.Intersect(p0, p1);
    return Intersection.FirstIntersection(list, ref p1)?.T ?? 0.0;
  }

  [Benchmark]
  public double RayBox_fast()
  {
    cube.IntersectFirst(c0, c1, 1.0, out SolidRecord h, out _);
    return h.T;
  }

  [Benchmark]
  public double RayBox_linkedlist()
  {
    LinkedList<Intersection>? list = cube.Intersect(c0, c1);
    return Intersection.FirstIntersection(list, ref c1)?.T ?? 0.0;
  }

  /// <summary>TriangleMesh (10,000-triangle torus): first accepted hit and CSG state through its BVH, no allocation.</summary>
  [Benchmark]
  public double RayMesh10k_fast()
  {
    torus.IntersectFirst(m0, m1, 1.0, out SolidRecord h, out _);
    return h.T;
  }

  [Benchmark]
  public double RayMesh10k_linkedlist()
  {
    LinkedList<Intersection>? list = torus.Intersect(m0, m1);
    return Intersection.FirstIntersection(list, ref m1)?.T ?? 0.0;
  }

  /// <summary>Möller–Trumbore on one triangle (the kernel inside MeshBvh).</summary>
  [Benchmark]
  public double RayTriangle()
  {
    Vector3d e1 = b - a, e2 = c - a;
    Vector3d pv = Vector3d.Cross(p1, e2);
    double det = Vector3d.Dot(e1, pv);
    if (System.Math.Abs(det) < 1e-12)
      return -1.0;
    double inv = 1.0 / det;
    Vector3d tv = p0 - a;
    double u = Vector3d.Dot(tv, pv) * inv;
    if (u < 0.0 || u > 1.0)
      return -1.0;
    Vector3d qv = Vector3d.Cross(tv, e1);
    double v = Vector3d.Dot(p1, qv) * inv;
    if (v < 0.0 || u + v > 1.0)
      return -1.0;
    return Vector3d.Dot(e2, qv) * inv;
  }
}
