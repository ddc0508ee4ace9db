using OpenTK.Mathematics;
using Rendering;
using static GrCis.Rendering.Tests.Solids.SolidTestSupport;

namespace GrCis.Rendering.Tests.Solids;

public class CubePlaneTests
{
  [Fact]
  public void Cube_ray_along_x_enters_negative_face_and_exits_positive_face()
  {
    var hits = Hits(new Cube(), new Vector3d(-1, 0.25, 0.75), new Vector3d(2, 0, 0));
    Assert.Equal(2, hits.Count);
    Assert.Equal(0.5, hits[0].T, 12);
    Assert.Equal(1.0, hits[1].T, 12);
    Assert.True(hits[0].Enter && hits[0].Front);
    Assert.False(hits[1].Enter);
    AssertVector(new Vector3d(-1, 0, 0), hits[0].NormalLocal);
    AssertVector(new Vector3d(1, 0, 0), hits[1].NormalLocal);
  }

  [Fact]
  public void Cube_parallel_ray_outside_slab_misses_inside_slab_hits()
  {
    Assert.Null(new Cube().Intersect(new Vector3d(-1, 1.5, 0.5), new Vector3d(1, 0, 0)));
    Assert.Equal(2, Hits(new Cube(), new Vector3d(-1, 0.5, 0.5), new Vector3d(1, 0, 0)).Count);
    Assert.Null(new Cube().Intersect(new Vector3d(-1, 2, 0.5), new Vector3d(1, 1, 0)));
  }

  [Theory]
  [InlineData(-1, 0.3, 0.6, 1, 0, 0, 0.3, 0.6)]   // −x face: (y, z)
  [InlineData(0.3, 2, 0.6, 0, -1, 0, 0.3, 0.6)]   // +y face: (x, z)
  [InlineData(0.3, 0.6, -2, 0, 0, 1, 0.3, 0.6)]   // −z face: (x, y)
  public void Cube_texture_coordinates_are_the_face_coordinates(double ox, double oy, double oz, double dx, double dy, double dz, double u, double v)
  {
    var root = Place(new Cube(), Matrix4d.Identity);
    Intersection i = First(root, new Vector3d(ox, oy, oz), new Vector3d(dx, dy, dz));
    Assert.Equal(u, i.TextureCoord.X, 12);
    Assert.Equal(v, i.TextureCoord.Y, 12);
    Assert.True(Vector3d.Dot(i.Normal, new Vector3d(dx, dy, dz)) < 0, "normal faces the ray origin");
  }

  [Fact]
  public void Cube_world_normal_follows_rotation()
  {
    var root = Place(new Cube(), Matrix4d.RotateY(System.Math.PI / 2));
    // RY(π/2) maps local +x to world −z... the face towards a ray from −z... check the normal is axis-aligned and faces the origin.
    Vector3d p0 = new Vector3d(0.5, 0.5, 5), p1 = new Vector3d(0, 0, -1);
    Intersection i = First(root, p0, p1);
    AssertOnRay(i, p0, p1);
    AssertVector(new Vector3d(0, 0, 1), i.Normal, 1e-12);
  }

  [Fact]
  public void Plane_single_hit_with_front_from_positive_z()
  {
    var hits = Hits(new Plane(), new Vector3d(1, 2, 3), new Vector3d(0, 0, -1));
    Assert.Single(hits);
    Assert.Equal(3.0, hits[0].T, 12);
    Assert.True(hits[0].Enter && hits[0].Front);
    var back = Hits(new Plane(), new Vector3d(1, 2, -3), new Vector3d(0, 0, 1));
    Assert.False(back[0].Front);
    Assert.Null(new Plane().Intersect(new Vector3d(0, 0, 1), new Vector3d(1, 0, 0)));
  }

  [Fact]
  public void Plane_rectangle_bounds_and_normalised_texture()
  {
    var rect = new Plane(-1, 3, 2, 4);
    Assert.Null(rect.Intersect(new Vector3d(3.5, 3, 1), new Vector3d(0, 0, -1)));
    var root = Place(rect, Matrix4d.Identity);
    Intersection i = First(root, new Vector3d(0, 3.5, 1), new Vector3d(0, 0, -1));
    Assert.Equal(0.25, i.TextureCoord.X, 12);
    Assert.Equal(0.75, i.TextureCoord.Y, 12);
  }

  [Fact]
  public void Plane_triangle_uses_reciprocal_bounds_and_barycentric_texture()
  {
    var tri = new Plane(2, 4);   // vertices (0,0), (2,0), (0,4)
    Assert.Equal(0.5, tri.XMax, 12);
    Assert.True(tri.Triangle);
    Assert.Null(tri.Intersect(new Vector3d(1.5, 1.5, 1), new Vector3d(0, 0, -1)));
    var root = Place(tri, Matrix4d.Identity);
    Intersection i = First(root, new Vector3d(1, 1, 1), new Vector3d(0, 0, -1));
    Assert.Equal(0.5, i.TextureCoord.X, 12);
    Assert.Equal(0.25, i.TextureCoord.Y, 12);
  }

  [Fact]
  public void Plane_floor_transform_gives_world_up_normal_on_both_sides()
  {
    // The classic floor: RX(−π/2)·T(0,−1,0): local +z → world +y.
    var root = Place(new Plane(), Matrix4d.RotateX(-System.Math.PI / 2) * Matrix4d.CreateTranslation(0, -1, 0));
    Vector3d p0 = new Vector3d(0.3, 2, -4), p1 = new Vector3d(0, -1, 0.5);
    Intersection i = First(root, p0, p1);
    AssertOnRay(i, p0, p1);
    Assert.Equal(-1.0, i.CoordWorld.Y, 12);
    AssertVector(new Vector3d(0, 1, 0), i.Normal, 1e-12);
    // Texture (u, v) = (x_world, −z_world).
    Assert.Equal(i.CoordWorld.X, i.TextureCoord.X, 12);
    Assert.Equal(-i.CoordWorld.Z, i.TextureCoord.Y, 12);
    // From below the plane still reports +z (GrCis planes never flip).
    Intersection below = First(root, new Vector3d(0, -3, 0), new Vector3d(0, 1, 0));
    AssertVector(new Vector3d(0, 1, 0), below.Normal, 1e-12);
  }
}
