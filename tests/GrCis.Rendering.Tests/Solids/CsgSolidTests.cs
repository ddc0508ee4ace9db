using System;
using OpenTK.Mathematics;
using Rendering;
using static GrCis.Rendering.Tests.Solids.SolidTestSupport;

namespace GrCis.Rendering.Tests.Solids;

// GrCis.Rendering.Tests.Math (main's math tests) would otherwise shadow System.Math here.
using Math = System.Math;

public class CsgSolidTests
{
  static CSGInnerNode CubeMinusSphere()
  {
    var diff = new CSGInnerNode(SetOperation.Difference);
    diff.InsertChild(new Cube(), Matrix4d.CreateTranslation(-0.5, -0.5, -0.5) * Matrix4d.Scale(2));   // [-1,1]³
    diff.InsertChild(new Sphere(), Matrix4d.Scale(1.2));
    return diff;
  }

  [Fact]
  public void Difference_of_cube_and_sphere_leaves_two_pieces_along_an_edge_ray()
  {
    var scene = CubeMinusSphere();
    Vector3d p0 = new Vector3d(-5, 0.8, 0.8), p1 = new Vector3d(1, 0, 0);
    var hits = Hits(scene, p0, p1);
    Assert.Equal(4, hits.Count);
    AssertSorted(hits);
    Assert.Equal(new[] { 4.0, 4.6, 5.4, 6.0 }, new[] { hits[0].T, hits[1].T, hits[2].T, hits[3].T }, new Tol(1e-9));
    Assert.Equal(new[] { true, false, true, false }, new[] { hits[0].Enter, hits[1].Enter, hits[2].Enter, hits[3].Enter });
  }

  [Fact]
  public void Difference_of_cube_and_sphere_is_empty_through_the_face_centres()
  {
    var hits = Hits(CubeMinusSphere(), new Vector3d(-5, 0, 0), new Vector3d(1, 0, 0));
    Assert.Empty(hits);
  }

  [Fact]
  public void Difference_hole_normals_point_into_the_hole_after_complete()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.InsertChild(CubeMinusSphere(), Matrix4d.CreateTranslation(3, 0, 0));
    Vector3d p0 = new Vector3d(-2, 0.8, 0.8), p1 = new Vector3d(1, 0, 0);
    var list = root.Intersect(p0, p1)!;
    var hits = new System.Collections.Generic.List<Intersection>(list);
    foreach (Intersection i in hits)
      i.Complete();
    // Leaving the material into the spherical hole at local x = −0.4: normal towards the hole centre.
    Vector3d toCentre = (new Vector3d(3, 0, 0) - hits[1].CoordWorld).Normalized();
    AssertVector(toCentre, hits[1].Normal, 1e-9);
    AssertVector(new Vector3d(0.4, -0.8, -0.8) / 1.2, hits[1].Normal, 1e-9);
    // Re-entering the material at x = +0.4: normal again towards the hole centre (facing the ray).
    AssertVector((new Vector3d(3, 0, 0) - hits[2].CoordWorld).Normalized(), hits[2].Normal, 1e-9);
    Assert.True(Vector3d.Dot(hits[2].Normal, p1) < 0);
    // Cube faces keep their outward normals.
    AssertVector(new Vector3d(-1, 0, 0), hits[0].Normal, 1e-12);
    AssertVector(new Vector3d(1, 0, 0), hits[3].Normal, 1e-12);
  }

  [Fact]
  public void Intersection_of_capped_cylinder_and_sphere_clips_the_caps()
  {
    var inter = new CSGInnerNode(SetOperation.Intersection);
    inter.InsertChild(new Cylinder(-2, 2), Matrix4d.Scale(0.5, 0.5, 1));
    inter.InsertChild(new Sphere(), Matrix4d.Identity);
    var hits = Hits(inter, new Vector3d(0, 0, -5), new Vector3d(0, 0, 1));
    Assert.Equal(2, hits.Count);
    Assert.Equal(4.0, hits[0].T, 12);   // the sphere, not the cap at z = −2
    Assert.Equal(6.0, hits[1].T, 12);
    Assert.Same(typeof(Sphere), hits[0].Solid!.GetType());
  }

  [Fact]
  public void Torus_minus_sphere_removes_the_near_tube()
  {
    var diff = new CSGInnerNode(SetOperation.Difference);
    diff.InsertChild(new Torus(2, 0.5), Matrix4d.Identity);
    diff.InsertChild(new Sphere(), Matrix4d.CreateTranslation(-2, 0, 0));
    var hits = Hits(diff, new Vector3d(-5, 0, 0), new Vector3d(1, 0, 0));
    Assert.Equal(2, hits.Count);
    Assert.Equal(6.5, hits[0].T, 9);
    Assert.Equal(7.5, hits[1].T, 9);
  }

  sealed class Tol : System.Collections.Generic.IEqualityComparer<double>
  {
    readonly double tol;
    public Tol(double tol) => this.tol = tol;
    public bool Equals(double a, double b) => Math.Abs(a - b) <= tol;
    public int GetHashCode(double d) => 0;
  }
}
