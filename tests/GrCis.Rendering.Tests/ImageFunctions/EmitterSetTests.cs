using System;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.ImageFunctions;

/// <summary>Which emissive solids the path tracer samples directly, and that a light sample's density is the one its ray gets by MIS.</summary>
public class EmitterSetTests
{
  static PhongMaterial Glow(double le) => new(new[] { 0.0, 0.0, 0.0 }, 0.0, 0.0, 0.0, 1) { Emission = new[] { le, le, le } };

  static (CSGInnerNode Root, Sphere Sphere) OneSphere(Matrix4d place, double le = 5.0)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    var sphere = new Sphere();
    sphere.SetAttribute(PropertyName.MATERIAL, Glow(le));
    root.InsertChild(sphere, place);
    return (root, sphere);
  }

  static readonly Matrix4d Similar =
    Matrix4d.Scale(0.3) * Matrix4d.CreateFromAxisAngle(new Vector3d(1, 2, 3).Normalized(), 0.7) * Matrix4d.CreateTranslation(1, 2, -0.5);

  [Fact]
  public void Similarities_are_told_from_other_transforms()
  {
    Assert.True(EmitterSet.Similarity(Similar, out double s));
    Assert.Equal(0.3, s, 12);
    Assert.True(EmitterSet.Similarity(Matrix4d.Scale(-2.0, 2.0, 2.0) * Matrix4d.RotateY(1.1), out s));   // mirrored
    Assert.Equal(2.0, s, 12);
    Assert.False(EmitterSet.Similarity(Matrix4d.Scale(1.0, 1.001, 1.0), out _));
    Assert.False(EmitterSet.Similarity(Matrix4d.Scale(0.5, 0.5, 0.8) * Matrix4d.RotateZ(0.3), out _));
    var shear = Matrix4d.Identity;
    shear.Row1 = new Vector4d(0.01, 1.0, 0.0, 0.0);
    Assert.False(EmitterSet.Similarity(shear, out _));
    Assert.False(EmitterSet.Similarity(Matrix4d.Scale(0.0), out _));
  }

  [Fact]
  public void Spheres_are_sampled_under_similarities_and_unions_only()
  {
    Assert.Equal(1, EmitterSet.Of(OneSphere(Similar).Root).Count);
    Assert.Equal(0, EmitterSet.Of(OneSphere(Matrix4d.Scale(0.3, 0.5, 0.3)).Root).Count);
    Assert.Equal(0, EmitterSet.Of(OneSphere(Similar, le: 0.0).Root).Count);

    // Mirrored by a parent (as the Cornell box's root is): still a sphere.
    var top = new CSGInnerNode(SetOperation.Union);
    top.InsertChild(OneSphere(Similar).Root, Matrix4d.Scale(-1.0, 1.0, 1.0));
    Assert.Equal(1, EmitterSet.Of(top).Count);

    // A difference may cut it; a subclass with other geometry is not a sphere.
    var difference = new CSGInnerNode(SetOperation.Difference);
    difference.InsertChild(OneSphere(Similar).Root, Matrix4d.Identity);
    Assert.Equal(0, EmitterSet.Of(difference).Count);
    var root = new CSGInnerNode(SetOperation.Union);
    var front = new SphereFront();
    front.SetAttribute(PropertyName.MATERIAL, Glow(5.0));
    root.InsertChild(front, Similar);
    Assert.Equal(0, EmitterSet.Of(root).Count);
  }

  [Fact]
  public void A_sphere_sample_lies_on_the_near_side_and_has_the_cone_density_the_scattered_ray_gets()
  {
    var (root, sphere) = OneSphere(Similar);
    EmitterSet set = EmitterSet.Of(root);
    Vector3d centre = new(1, 2, -0.5);
    const double r = 0.3;
    Vector3d x = new(-0.4, 0.9, 0.7);
    double d2 = (centre - x).LengthSquared;
    double cone = 1.0 / (2.0 * Math.PI * (1.0 - Math.Sqrt(1.0 - r * r / d2)));

    for (int i = 0; i < 16; i++)
      for (int j = 0; j < 16; j++)
      {
        Assert.True(set.Sample(x, 0.5, (i + 0.5) / 16, (j + 0.5) / 16, out Vector3d toLight, out double dist, out Vector3d wi, out _, out double pdf));
        Vector3d hit = x + toLight;
        Vector3d normal = (hit - centre) / r;
        Assert.Equal(r, (hit - centre).Length, 9);
        Assert.Equal(dist, toLight.Length, 1e-12 * dist);
        Assert.Equal(1.0, wi.Length, 12);
        Assert.True(Vector3d.Dot(normal, wi) < 0.0, "the sample must see the outer, emitting side");
        Assert.Equal(cone, pdf, 6);
        Assert.True(set.Pdf(sphere, x, hit, normal, wi, out double misPdf));
        Assert.Equal(pdf, misPdf, 1e-12 * pdf);
      }
  }

  [Fact]
  public void From_inside_or_on_a_sphere_there_is_no_sample_and_a_zero_density()
  {
    var (root, sphere) = OneSphere(Similar);
    EmitterSet set = EmitterSet.Of(root);
    Vector3d centre = new(1, 2, -0.5);
    foreach (Vector3d x in new[] { centre, centre + new Vector3d(0.1, 0.0, 0.0), centre + new Vector3d(0.0, 0.3, 0.0) })
    {
      Assert.False(set.Sample(x, 0.5, 0.3, 0.6, out _, out _, out _, out _, out _));
      Assert.True(set.Pdf(sphere, x, centre + new Vector3d(0.3, 0.0, 0.0), Vector3d.UnitX, -Vector3d.UnitX, out double pdf));
      Assert.Equal(0.0, pdf);
    }
  }

  [Fact]
  public void Rectangles_and_spheres_are_picked_in_proportion_to_area_times_radiance()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    var quad = new Plane(-1, 1, -0.5, 0.5);   // area 2
    quad.SetAttribute(PropertyName.MATERIAL, Glow(3.0));
    root.InsertChild(quad, Matrix4d.RotateX(MathHelper.PiOver2) * Matrix4d.CreateTranslation(0, 4, 0));
    var sphere = new Sphere();
    sphere.SetAttribute(PropertyName.MATERIAL, Glow(2.0));
    root.InsertChild(sphere, Matrix4d.Scale(0.5) * Matrix4d.CreateTranslation(3, 1, 0));
    EmitterSet set = EmitterSet.Of(root);
    Assert.Equal(2, set.Count);

    double quadPower = 2.0 * 3.0, spherePower = 4.0 * Math.PI * 0.25 * 2.0, total = quadPower + spherePower;
    Vector3d x = Vector3d.Zero;
    Assert.True(set.Pdf(sphere, x, new Vector3d(2.5, 1, 0), -Vector3d.UnitX, Vector3d.UnitX, out double pdf));
    double sin2 = 0.25 / 10.0;
    double solidAngle = 2.0 * Math.PI * (1.0 - Math.Sqrt(1.0 - sin2));
    Assert.Equal(spherePower / total, pdf * solidAngle, 9);

    // The rectangle: pick probability / area per unit area, turned to solid angle (distance 4, straight below its centre).
    Assert.True(set.Pdf(quad, x, new Vector3d(0, 4, 0), -Vector3d.UnitY, Vector3d.UnitY, out pdf));
    Assert.Equal(quadPower / total / 2.0 * 16.0, pdf, 9);
  }
}
