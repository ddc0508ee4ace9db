using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>
/// The one decision whether a script's subclass still behaves as the library type: a subclass that overrides
/// nothing relevant keeps the shortcuts, one that overrides something relevant loses only that part.
/// </summary>
public class SubclassCheckTests
{
  // Script-style subclasses: the first changes nothing but its construction.
  sealed class NamedSphere : Sphere
  {
    public string Name = "ball";
  }

  sealed class ShadedSphere : Sphere
  {
    public override void CompleteIntersection(Intersection inter)
    {
      base.CompleteIntersection(inter);
      inter.TextureCoord = Vector2d.Zero;
    }
  }

  sealed class BiggerSphere : Sphere
  {
    public override void GetBoundingBox(out Vector3d corner1, out Vector3d corner2)
    {
      corner1 = new Vector3d(-2.0);
      corner2 = new Vector3d(2.0);
    }
  }

  sealed class HollowSphere : Sphere
  {
    public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1) => null;
  }

  sealed class TintedPhong : PhongMaterial
  {
    public TintedPhong() : base(new[] { 1.0, 0.5, 0.0 }, 0.1, 0.6, 0.3, 8) { }
  }

  sealed class QuietTracing : RayTracing
  {
    public int Frames;
  }

  sealed class PickyTracing : RayTracing
  {
    public override long shade(int depth, double importance, ref Vector3d p0, ref Vector3d p1, double[] color) =>
      base.shade(depth, importance, ref p0, ref p1, color);
  }

  [Fact]
  public void A_subclass_overriding_nothing_behaves_as_the_library_type()
  {
    Assert.True(SubclassCheck.OverridesNothing(new Sphere(), typeof(Sphere)));
    Assert.True(SubclassCheck.OverridesNothing(new NamedSphere(), typeof(Sphere)));
    Assert.True(SubclassCheck.OverridesNothing(new TintedPhong(), typeof(PhongMaterial)));
    Assert.False(SubclassCheck.OverridesNothing(new ShadedSphere(), typeof(Sphere)));
    Assert.False(SubclassCheck.OverridesNothing(new SphereFront(), typeof(Sphere)));   // a library subclass with its own records
    Assert.False(SubclassCheck.OverridesNothing(new Cube(), typeof(Sphere)));
    Assert.False(SubclassCheck.OverridesNothing(null, typeof(Sphere)));
    Assert.False(SubclassCheck.OverridesNothing(new AnimatedCSGInnerNode(SetOperation.Union), typeof(CSGInnerNode)));   // adds ITimeDependent
  }

  [Fact]
  public void Only_intersect_and_bounding_box_overrides_change_the_records()
  {
    Assert.True(SubclassCheck.KeepsGeometry(new NamedSphere(), typeof(Sphere)));
    Assert.True(SubclassCheck.KeepsGeometry(new ShadedSphere(), typeof(Sphere)));
    Assert.False(SubclassCheck.KeepsGeometry(new BiggerSphere(), typeof(Sphere)));
    Assert.False(SubclassCheck.KeepsGeometry(new HollowSphere(), typeof(Sphere)));
    Assert.True(new ShadedSphere().RecordsMatchIntersect);
    Assert.False(new HollowSphere().RecordsMatchIntersect);
  }

  [Fact]
  public void Every_hit_reader_name_is_an_overridable_method_of_the_ray_tracer()
  {
    // A misspelt or renamed name would silently stop a script's override from being noticed.
    const System.Reflection.BindingFlags all = System.Reflection.BindingFlags.Instance | System.Reflection.BindingFlags.Public | System.Reflection.BindingFlags.NonPublic;
    Assert.Equal(5, RayCasting.HitReaders.Count);
    foreach (string name in RayCasting.HitReaders)
      Assert.Contains(typeof(RayTracing).GetMethods(all), m => m.Name == name && m.IsVirtual && !m.IsFinal);
  }

  [Fact]
  public void Only_script_classes_overriding_a_hit_reader_read_whole_hits()
  {
    Assert.False(SubclassCheck.OverridesAny(typeof(RayTracing), RayCasting.HitReaders));
    Assert.False(SubclassCheck.OverridesAny(typeof(QuietTracing), RayCasting.HitReaders));
    Assert.True(SubclassCheck.OverridesAny(typeof(PickyTracing), RayCasting.HitReaders));
    Assert.False(SubclassCheck.OverridesAny(typeof(PickyTracing), new[] { "Occluded" }));
  }

  [Fact]
  public void A_plain_subclass_keeps_the_surface_completion_and_a_shading_one_gets_the_full_one()
  {
    var r = new System.Random(3);
    PreparedScene named = Prepared(new NamedSphere()), shaded = Prepared(new ShadedSphere()), plain = Prepared(new Sphere());
    int hits = 0;
    for (int n = 0; n < 2000; n++)
    {
      var p0 = new Vector3d(r.NextDouble() - 0.5, r.NextDouble() - 0.5, -5.0);
      var p1 = new Vector3d(0.0, 0.0, 1.0);
      Intersection? a = plain.FirstHit(p0, p1, new Intersection(), surfaceOnly: true);
      Intersection? b = named.FirstHit(p0, p1, new Intersection(), surfaceOnly: true);
      Intersection? c = shaded.FirstHit(p0, p1, new Intersection(), surfaceOnly: true);
      if (a == null)
        continue;
      hits++;
      // Surface completion leaves the tangents out: the plain subclass gets the same, the overriding one its own completion.
      Assert.Equal(a.TangentU, b!.TangentU);
      Assert.Equal(a.CoordWorld, b.CoordWorld);
      Assert.NotEqual(Vector3d.Zero, c!.TangentU);
      Assert.Equal(Vector2d.Zero, c.TextureCoord);
    }
    Assert.True(hits > 1000);
  }

  static PreparedScene Prepared(Sphere ball)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.5, 0.5, 0.5 }, 0.1, 0.6, 0.3, 16));
    root.InsertChild(ball, Matrix4d.Identity);
    root.InsertChild(new Cube(), Matrix4d.CreateTranslation(3.0, 0.0, 0.0));
    return PreparedScene.Prepare(root);
  }
}
