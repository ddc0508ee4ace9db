using OpenTK.Mathematics;
using Rendering;
using static GrCis.Rendering.Tests.Solids.SolidTestSupport;

namespace GrCis.Rendering.Tests.Solids;

public class CylinderTests
{
  [Fact]
  public void Cylinder_infinite_side_hits_twice()
  {
    var hits = Hits(new Cylinder(), new Vector3d(-3, 0, 7), new Vector3d(1, 0, 0));
    Assert.Equal(2, hits.Count);
    Assert.Equal(2.0, hits[0].T, 12);
    Assert.Equal(4.0, hits[1].T, 12);
    Assert.True(hits[0].Enter);
    Assert.False(hits[1].Enter);
  }

  [Fact]
  public void Cylinder_capped_oblique_ray_enters_through_cap_and_exits_side()
  {
    var cyl = new Cylinder(0, 1);
    // From above, going down and sideways.
    var hits = Hits(cyl, new Vector3d(0, 0, 2), new Vector3d(0.5, 0, -1));
    Assert.Equal(2, hits.Count);
    Assert.Equal(1.0, hits[0].T, 12);      // z = 1 cap at x = 0.5
    AssertVector(new Vector3d(0, 0, 1), hits[0].NormalLocal);
    Assert.Equal(2.0, hits[1].T, 12);      // side at x = 1, z = 0 → exactly the rim; side wins
    Assert.True(hits[0].Enter && !hits[1].Enter);
  }

  [Fact]
  public void Cylinder_ray_along_axis_crosses_both_caps()
  {
    var hits = Hits(new Cylinder(-0.5, 0.5), new Vector3d(0.2, 0.3, -2), new Vector3d(0, 0, 1));
    Assert.Equal(2, hits.Count);
    Assert.Equal(1.5, hits[0].T, 12);
    Assert.Equal(2.5, hits[1].T, 12);
    AssertVector(new Vector3d(0, 0, -1), hits[0].NormalLocal);
    Assert.Null(new Cylinder().Intersect(new Vector3d(0.2, 0.3, -2), new Vector3d(0, 0, 1)));
  }

  [Fact]
  public void Cylinder_ray_missing_the_finite_part_returns_null()
  {
    Assert.Null(new Cylinder(0, 1).Intersect(new Vector3d(-3, 0, 2), new Vector3d(1, 0, 0)));
  }

  [Fact]
  public void Cylinder_texture_is_longitude_and_z_and_caps_have_u_zero()
  {
    var root = Place(new Cylinder(-1, 1), Matrix4d.Identity);
    Intersection side = First(root, new Vector3d(0, -5, 0.4), new Vector3d(0, 1, 0));
    Assert.Equal(0.25, side.TextureCoord.X, 12);
    Assert.Equal(0.4, side.TextureCoord.Y, 12);
    AssertVector(new Vector3d(0, -1, 0), side.Normal, 1e-12);
    Intersection cap = First(root, new Vector3d(0.3, 0.2, 5), new Vector3d(0, 0, -1));
    Assert.Equal(0.0, cap.TextureCoord.X, 12);
    Assert.Equal(1.0, cap.TextureCoord.Y, 12);
    AssertVector(new Vector3d(0, 0, 1), cap.Normal, 1e-12);
  }

  [Fact]
  public void CylinderFront_rejects_cap_entry_and_reports_front_side_only()
  {
    var cf = new CylinderFront(-1, 1);
    Assert.Null(cf.Intersect(new Vector3d(0, 0, 5), new Vector3d(0.1, 0, -1)));
    var hits = Hits(cf, new Vector3d(-5, 0.6, 0), new Vector3d(1, 0, 0));
    Assert.Equal(2, hits.Count);
    Assert.Equal(Intersection.SHELL_THICKNESS, hits[1].T - hits[0].T, 12);
    var root = Place(new CylinderFront(false), Matrix4d.Identity);
    Intersection i = First(root, new Vector3d(-5, 0.6, 0), new Vector3d(1, 0, 0));
    Assert.Equal(0.6, i.TextureCoord.X, 9);
  }
}
