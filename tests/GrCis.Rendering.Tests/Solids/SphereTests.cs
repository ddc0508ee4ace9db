using System;
using OpenTK.Mathematics;
using Rendering;
using static GrCis.Rendering.Tests.Solids.SolidTestSupport;

namespace GrCis.Rendering.Tests.Solids;

// GrCis.Rendering.Tests.Math (main's math tests) would otherwise shadow System.Math here.
using Math = System.Math;

public class SphereTests
{
  [Fact]
  public void Sphere_ray_from_outside_hits_twice_sorted_by_t()
  {
    var hits = Hits(new Sphere(), new Vector3d(0, 0, -5), new Vector3d(0, 0, 2));
    Assert.Equal(2, hits.Count);
    Assert.Equal(2.0, hits[0].T, 12);
    Assert.Equal(3.0, hits[1].T, 12);
    Assert.True(hits[0].Enter && hits[0].Front);
    Assert.False(hits[1].Enter || hits[1].Front);
    AssertVector(new Vector3d(0, 0, -1), hits[0].CoordLocal);
  }

  [Fact]
  public void Sphere_ray_from_inside_reports_negative_entry_then_exit()
  {
    var hits = Hits(new Sphere(), new Vector3d(0.2, 0, 0), new Vector3d(1, 0, 0));
    Assert.Equal(2, hits.Count);
    Assert.Equal(-1.2, hits[0].T, 12);
    Assert.Equal(0.8, hits[1].T, 12);
  }

  [Fact]
  public void Sphere_miss_and_zero_direction_return_null()
  {
    Assert.Null(new Sphere().Intersect(new Vector3d(0, 2, -5), new Vector3d(0, 0, 1)));
    Assert.Null(new Sphere().Intersect(new Vector3d(0, 0, -5), Vector3d.Zero));
  }

  [Fact]
  public void Sphere_far_origin_keeps_precision()
  {
    // Naive b² − 4ac loses everything here; the stable form keeps ~1e-9 relative accuracy.
    var hits = Hits(new Sphere(), new Vector3d(0.5, 0, -1e7), new Vector3d(0, 0, 1));
    Assert.Equal(2, hits.Count);
    double half = Math.Sqrt(0.75);
    Assert.Equal(1e7 - half, hits[0].T, 6);
    Assert.Equal(1e7 + half, hits[1].T, 6);
  }

  [Fact]
  public void Sphere_world_normal_under_nonuniform_scale_is_the_cofactor_transform()
  {
    // Ellipsoid x²/4 + y² + z² = 1, shifted; point (1, √3/2... ) chosen on its surface.
    var sphere = new Sphere();
    var root = Place(sphere, Matrix4d.Scale(2, 1, 1) * Matrix4d.CreateTranslation(10, 0, 0));
    Vector3d p0 = new Vector3d(11, 0, -5), p1 = new Vector3d(0, 0, 1);
    Intersection i = First(root, p0, p1);
    AssertOnRay(i, p0, p1);
    // Local hit (0.5, 0, -√0.75); the ellipsoid's gradient there ∝ (x/4, y, z) in world-centred coords.
    Vector3d c = i.CoordWorld - new Vector3d(10, 0, 0);
    Vector3d expected = new Vector3d(c.X / 4, c.Y, c.Z).Normalized();
    AssertVector(expected, i.Normal, 1e-9);
    Assert.Equal(1.0, i.Normal.Length, 12);
  }

  [Fact]
  public void Sphere_exit_normal_stays_outward_as_in_GrCis()
  {
    // Enter == Front on the exit, so Complete() does not flip: the normal points out of the solid.
    var root = Place(new Sphere(), Matrix4d.Identity);
    Vector3d p0 = Vector3d.Zero, p1 = new Vector3d(0, 0, 1);
    Intersection i = First(root, p0, p1);
    Assert.False(i.Enter);
    AssertVector(new Vector3d(0, 0, 1), i.Normal);
  }

  [Fact]
  public void Sphere_texture_coordinates_follow_longitude_and_polar_angle()
  {
    var root = Place(new Sphere(), Matrix4d.Identity);
    // Hit at (-1, 0, 0): u = atan2(0,-1)/2π + 0.5 = 1.0 → wraps as 1; at (0,-1,0): u = 0.25.
    Intersection i = First(root, new Vector3d(0, -5, 0), new Vector3d(0, 1, 0));
    Assert.Equal(0.25, i.TextureCoord.X, 12);
    Assert.Equal(0.5, i.TextureCoord.Y, 12);
    Intersection top = First(root, new Vector3d(0, 0, 5), new Vector3d(0, 0, -1));
    Assert.Equal(0.0, top.TextureCoord.Y, 12);
    // Tangent U points east (growing u), tangent V towards −z.
    Intersection eq = First(root, new Vector3d(5, 0, 0.3), new Vector3d(-1, 0, 0));
    Assert.True(eq.TangentU.Y > 0.99);
    Assert.True(eq.TangentV.Z < -0.9);
  }

  [Fact]
  public void SphereFront_returns_front_hit_and_thin_shell_exit()
  {
    var hits = Hits(new SphereFront(), new Vector3d(0, 0, -5), new Vector3d(0, 0, 1));
    Assert.Equal(2, hits.Count);
    Assert.Equal(4.0, hits[0].T, 12);
    Assert.True(hits[0].Enter);
    Assert.Equal(4.0 + Intersection.SHELL_THICKNESS, hits[1].T, 12);
    Assert.False(hits[1].Enter);
    Assert.Single(Hits(new SphereFront(false), new Vector3d(0, 0, -5), new Vector3d(0, 0, 1)));
  }

  [Fact]
  public void SphereFront_texture_is_projected_distance_from_centre()
  {
    var root = Place(new SphereFront(false), Matrix4d.Identity);
    Assert.Equal(0.0, First(root, new Vector3d(0, 0, -5), new Vector3d(0, 0, 1)).TextureCoord.X, 9);
    Intersection i = First(root, new Vector3d(0.6, 0, -5), new Vector3d(0, 0, 1));
    Assert.Equal(0.6, i.TextureCoord.X, 9);
    Assert.Equal(0.6, i.TextureCoord.Y, 9);
  }
}
