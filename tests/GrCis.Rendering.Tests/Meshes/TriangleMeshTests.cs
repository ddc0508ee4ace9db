using Scene3D;
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using OpenTK.Mathematics;
using Rendering;
using static GrCis.Rendering.Tests.Meshes.MeshTestSupport;
using static GrCis.Rendering.Tests.Solids.SolidTestSupport;

namespace GrCis.Rendering.Tests.Meshes;

public class TriangleMeshTests
{
  [Fact]
  public void TriangleMesh_closed_cube_enters_and_exits_like_the_cube_solid()
  {
    var mesh = new TriangleMesh(Read(CubeObj));
    var cube = new Cube();
    var rnd = new Random(7);
    int compared = 0;
    for (int n = 0; n < 2000; n++)
    {
      Vector3d p0 = new Vector3d(rnd.NextDouble() * 4 - 1.5, rnd.NextDouble() * 4 - 1.5, rnd.NextDouble() * 4 - 1.5);
      Vector3d target = new Vector3d(rnd.NextDouble(), rnd.NextDouble(), rnd.NextDouble());
      Vector3d p1 = (target - p0) * (0.5 + rnd.NextDouble());
      var a = Hits(mesh, p0, p1);
      var b = Hits(cube, p0, p1);
      Assert.Equal(b.Count, a.Count);
      for (int i = 0; i < a.Count; i++)
      {
        Assert.Equal(b[i].T, a[i].T, 9);
        Assert.Equal(b[i].Enter, a[i].Enter);
        Assert.Equal(a[i].Enter, a[i].Front);
      }
      compared += a.Count;
    }
    Assert.True(compared > 3000);
  }

  [Fact]
  public void TriangleMesh_ray_through_a_shared_edge_is_reported_once()
  {
    var mesh = new TriangleMesh(Read(CubeObj));
    // The quad x = 0 is split along a diagonal; aim exactly at the diagonal's middle and at a cube edge.
    var hits = Hits(mesh, new Vector3d(-1, 0.5, 0.5), new Vector3d(1, 0, 0));
    Assert.Equal(2, hits.Count);
    var edge = Hits(mesh, new Vector3d(-1, 0.5, -1), new Vector3d(1, 0, 1));   // through edge x=0,z=0
    Assert.True(edge.Count % 2 == 0, $"got {edge.Count} hits");
  }

  [Fact]
  public void TriangleMesh_normals_flat_and_smooth_after_complete()
  {
    const string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn -1 0 1\nvn 1 0 1\nvn 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1/1 2/2/2 3/3/3\n";
    var smooth = new TriangleMesh(Read(obj));
    var root = Place(smooth, Matrix4d.CreateTranslation(0, 0, 5));
    Vector3d p0 = new Vector3d(0.5, 0.25, 10), p1 = new Vector3d(0, 0, -1);
    Intersection i = First(root, p0, p1);
    AssertOnRay(i, p0, p1);
    Assert.True(i.Enter && i.Front);
    // Barycentric weights (0.25, 0.5, 0.25): n ∝ 0.25(−1,0,1) + 0.5(1,0,1) + 0.25(0,0,1) = (0.25, 0, 1).
    AssertVector(new Vector3d(0.25, 0, 1).Normalized(), i.Normal, 1e-6);
    Assert.Equal(0.5, i.TextureCoord.X, 6);
    Assert.Equal(0.25, i.TextureCoord.Y, 6);
    AssertVector(Vector3d.UnitX, i.TangentU, 1e-9);

    var flat = new TriangleMesh(Read(obj)) { Smooth = false };
    Intersection f = First(Place(flat, Matrix4d.Identity), new Vector3d(0.5, 0.25, 1), p1);
    AssertVector(Vector3d.UnitZ, f.Normal, 1e-12);
    // From the back: Enter = Front = false, normal unchanged (outward).
    var back = Hits(flat, new Vector3d(0.2, 0.2, -1), new Vector3d(0, 0, 1));
    Assert.False(back[0].Front);
  }

  [Fact]
  public void TriangleMesh_shell_mode_adds_an_exit_behind_each_crossing()
  {
    var mesh = new TriangleMesh(Read("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")) { ShellMode = true };
    var hits = Hits(mesh, new Vector3d(0.2, 0.2, -1), new Vector3d(0, 0, 1));
    Assert.Equal(2, hits.Count);
    Assert.True(hits[0].Enter);
    Assert.False(hits[1].Enter);
    Assert.Equal(TriangleMesh.SHELL_OFFSET, hits[1].T - hits[0].T, 12);
  }

  [Fact]
  public void TriangleMesh_in_csg_difference_matches_cube_solid()
  {
    CSGInnerNode Make(ISceneNode box)
    {
      var d = new CSGInnerNode(SetOperation.Difference);
      d.InsertChild(box, Matrix4d.CreateTranslation(-0.5, -0.5, -0.5) * Matrix4d.Scale(2));
      d.InsertChild(new Sphere(), Matrix4d.Scale(1.2));
      return d;
    }
    var a = Hits(Make(new TriangleMesh(Read(CubeObj))), new Vector3d(-5, 0.8, 0.8), new Vector3d(1, 0, 0));
    var b = Hits(Make(new Cube()), new Vector3d(-5, 0.8, 0.8), new Vector3d(1, 0, 0));
    Assert.Equal(b.Select(h => (System.Math.Round(h.T, 9), h.Enter)), a.Select(h => (System.Math.Round(h.T, 9), h.Enter)));
  }

  [Fact]
  public void TriangleMesh_bvh_finds_the_same_hits_as_brute_force_on_the_teapot()
  {
    var scene = new SceneBrep();
    new WavefrontObj().ReadBrep(Path.Combine(MeshDir, "teapot.obj.gz"), scene);
    var mesh = new TriangleMesh(scene);
    float diameter = scene.GetDiameter(out Vector3 centerF);
    Vector3d center = centerF;
    Assert.True(mesh.Bvh.NodeCount > 100);

    var rnd = new Random(11);
    int totalHits = 0;
    for (int n = 0; n < 300; n++)
    {
      Vector3d p0 = center + new Vector3d(rnd.NextDouble() - 0.5, rnd.NextDouble() - 0.5, rnd.NextDouble() - 0.5) * 2 * diameter;
      Vector3d target = center + new Vector3d(rnd.NextDouble() - 0.5, rnd.NextDouble() - 0.5, rnd.NextDouble() - 0.5) * 0.5 * diameter;
      Vector3d p1 = target - p0;
      var ours = Hits(mesh, p0, p1);
      AssertSorted(ours);

      // Brute force over all triangles (independent Möller–Trumbore).
      var brute = new List<double>();
      for (int t = 0; t < scene.Triangles; t++)
      {
        scene.GetTriangleVertices(t, out Vector3 a, out Vector3 b, out Vector3 c);
        if (RayTriangle(p0, p1, a, b, c, out double tt))
          brute.Add(tt);
      }
      brute.Sort();
      // Edge hits are deduplicated by the mesh: compare the distinct values.
      var distinct = new List<double>();
      foreach (double t in brute)
        if (distinct.Count == 0 || t - distinct[^1] > 1e-9)
          distinct.Add(t);
      Assert.Equal(distinct.Count, ours.Count);
      for (int k = 0; k < ours.Count; k++)
        Assert.Equal(distinct[k], ours[k].T, 9);
      totalHits += ours.Count;
    }
    Assert.True(totalHits > 200, $"only {totalHits} hits");
  }

  static bool RayTriangle(Vector3d o, Vector3d d, Vector3d a, Vector3d b, Vector3d c, out double t)
  {
    t = 0;
    Vector3d e1 = b - a, e2 = c - a;
    Vector3d p = Vector3d.Cross(d, e2);
    double det = Vector3d.Dot(e1, p);
    if (det == 0) return false;
    Vector3d s = o - a;
    double u = Vector3d.Dot(s, p) / det;
    if (u < 0 || u > 1) return false;
    Vector3d q = Vector3d.Cross(s, e1);
    double v = Vector3d.Dot(d, q) / det;
    if (v < 0 || u + v > 1) return false;
    t = Vector3d.Dot(e2, q) / det;
    return true;
  }
}
