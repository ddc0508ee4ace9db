using System;
using System.Collections.Generic;
using System.IO;
using GrCis.Testing;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Rendering.Imaging;
using Xunit.Abstractions;

namespace GrCis.Rendering.Tests.SceneGraph;

/// <summary>
/// GrCis's completion contract: a solid may leave the world normal zero and fill only its local normal or only
/// its local tangents; completion derives the rest. Students' solids written since 2020 rely on it.
/// </summary>
public class CompletionContractTests(ITestOutputHelper output)
{
  /// <summary>A unit sphere written as a student writes one: the hits carry their points, nothing else.</summary>
  abstract class StudentSphere : DefaultSceneNode, ISolid
  {
    public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
    {
      double dd = Vector3d.Dot(p1, p1);
      double od = Vector3d.Dot(p0, p1);
      double oo = Vector3d.Dot(p0, p0);
      double d = od * od + dd * (1.0 - oo);
      if (d <= 0.0)
        return null;
      d = Math.Sqrt(d);
      var list = new LinkedList<Intersection>();
      double t = (-od - d) / dd;
      list.AddLast(Hit(t, p0 + t * p1, true));
      t = (-od + d) / dd;
      list.AddLast(Hit(t, p0 + t * p1, false));
      return list;
    }

    protected virtual Intersection Hit(double t, Vector3d local, bool enter) =>
      new(this) { T = t, Enter = enter, Front = enter, CoordLocal = local };

    public void GetBoundingBox(out Vector3d corner1, out Vector3d corner2)
    {
      corner1 = new Vector3d(-1.0);
      corner2 = new Vector3d(1.0);
    }
  }

  /// <summary>GrCis's own Sphere since 2020: the local normal set with the hit, completion adds nothing.</summary>
  sealed class NormalInHitSphere : StudentSphere
  {
    protected override Intersection Hit(double t, Vector3d local, bool enter)
    {
      Intersection i = base.Hit(t, local, enter);
      i.NormalLocal = local;
      return i;
    }
  }

  /// <summary>Fills only the local normal, in CompleteIntersection.</summary>
  sealed class NormalLocalSphere : StudentSphere
  {
    public override void CompleteIntersection(Intersection inter) => inter.NormalLocal = inter.CoordLocal;
  }

  /// <summary>Fills only the local tangents (east, then north: their cross product points out).</summary>
  sealed class TangentSphere : StudentSphere
  {
    public override void CompleteIntersection(Intersection inter)
    {
      Vector3d p = inter.CoordLocal;
      double r2 = p.X * p.X + p.Y * p.Y;
      if (r2 < 1e-20)
      {
        inter.TangentU = Vector3d.UnitX;
        inter.TangentV = new Vector3d(0.0, Math.Sign(p.Z) >= 0 ? 1.0 : -1.0, 0.0);
        return;
      }
      inter.TangentU = new Vector3d(-p.Y, p.X, 0.0);
      inter.TangentV = new Vector3d(-p.Z * p.X, -p.Z * p.Y, r2);
    }
  }

  /// <summary>Before 2020 a solid set the world normal itself; that is kept.</summary>
  sealed class WorldNormalSphere : StudentSphere
  {
    public override void CompleteIntersection(Intersection inter) =>
      inter.Normal = Vector3d.TransformNormalInverse(inter.CoordLocal, inter.WorldToLocal);
  }

  sealed class SilentSphere : StudentSphere { }

  static readonly Matrix4d Squash = Matrix4d.Scale(1.6, 0.7, 1.1) * Matrix4d.RotateZ(0.5) * Matrix4d.CreateTranslation(0.3, 0.2, 0.5);

  static Intersection CompletedHit(ISolid solid)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.InsertChild(solid, Squash);
    Matrix4d toLocal = Squash.Inverted();
    Vector3d p0 = Vector3d.TransformPosition(new Vector3d(-0.9, 1.3, -6.0), toLocal);
    Vector3d p1 = Vector3d.TransformVector(new Vector3d(0.1, -0.2, 1.0), toLocal);
    Intersection hit = Intersection.FirstIntersection(solid.Intersect(p0, p1), ref p1)!;
    hit.Complete();
    return hit;
  }

  static void AssertSameDirection(Vector3d expected, Vector3d actual)
  {
    Assert.True(Vector3d.Dot(expected.Normalized(), actual.Normalized()) > 1.0 - 1e-12, $"expected {expected}, got {actual}");
  }

  [Fact]
  public void A_solid_filling_only_the_local_normal_gets_tangents_and_the_world_normal_of_the_library_sphere()
  {
    Intersection library = CompletedHit(new Sphere());
    Intersection student = CompletedHit(new NormalLocalSphere());

    Assert.Equal(1.0, student.Normal.Length, 12);
    AssertSameDirection(library.Normal, student.Normal);
    // GrCis's tangents of the local normal: "north" and "east", in local space, their cross product the normal.
    MathSupport.Geometry.GetTangents(ref student.NormalLocal, out Vector3d north, out Vector3d east);
    Assert.Equal(north, student.TangentU);
    Assert.Equal(east, student.TangentV);
    AssertSameDirection(student.NormalLocal, Vector3d.Cross(student.TangentU, student.TangentV));
  }

  [Fact]
  public void A_solid_filling_only_the_tangents_gets_the_local_normal_from_their_cross_product()
  {
    Intersection library = CompletedHit(new Sphere());
    Intersection student = CompletedHit(new TangentSphere());

    AssertSameDirection(library.Normal, student.Normal);
    AssertSameDirection(student.CoordLocal, student.NormalLocal);
    Assert.Equal(Vector3d.Cross(student.TangentU, student.TangentV), student.NormalLocal);
  }

  [Fact]
  public void A_world_normal_set_by_the_solid_is_kept()
  {
    Intersection library = CompletedHit(new Sphere());
    Intersection student = CompletedHit(new WorldNormalSphere());
    AssertSameDirection(library.Normal, student.Normal);
    // Tangents are still derived (from the zero local normal: GrCis's fallback pair), without touching the normal.
    Assert.Equal(Vector3d.UnitX, student.TangentU);
    Assert.Equal(Vector3d.UnitY, student.TangentV);
  }

  [Fact]
  public void A_solid_filling_nothing_gets_the_local_z_axis_not_a_NaN()
  {
    Intersection hit = CompletedHit(new SilentSphere());
    Vector3d expected = Vector3d.TransformNormalInverse(Vector3d.UnitZ, Squash.Inverted());
    if (hit.Enter != hit.Front)
      expected = -expected;
    Assert.False(double.IsNaN(hit.Normal.X + hit.Normal.Y + hit.Normal.Z));
    AssertSameDirection(expected, hit.Normal);
  }

  [Fact]
  public void The_library_solids_frames_are_unchanged()
  {
    // The library's solids fill all three; the contract only fills what is zero.
    Intersection hit = CompletedHit(new Sphere());
    AssertSameDirection(hit.CoordLocal, hit.NormalLocal);
    Assert.Equal(1.0, hit.TangentU.Length, 12);   // world-space unit tangents, as Sphere writes them
    Assert.Equal(1.0, hit.TangentV.Length, 12);
  }

  // ------------------------------------------------------------------ rendered next to the library's Sphere

  static DefaultRayScene Scene(Func<ISolid> ball)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.5, 0.5, 0.5 }, 0.1, 0.6, 0.4, 24));
    ISolid a = ball();
    a.SetAttribute(PropertyName.COLOR, new[] { 1.0, 0.6, 0.1 });
    root.InsertChild(a, Squash);
    ISolid b = ball();
    b.SetAttribute(PropertyName.COLOR, new[] { 0.2, 0.5, 1.0 });
    root.InsertChild(b, Matrix4d.Scale(0.6) * Matrix4d.CreateTranslation(-1.8, -0.4, -0.8));
    var floor = new Plane();
    floor.SetAttribute(PropertyName.COLOR, new[] { 0.7, 0.7, 0.7 });
    root.InsertChild(floor, Matrix4d.RotateX(-Math.PI / 2) * Matrix4d.CreateTranslation(0, -1.2, 0));
    return new DefaultRayScene
    {
      Intersectable = root,
      BackgroundColor = new[] { 0.0, 0.05, 0.07 },
      Camera = new StaticCamera(new Vector3d(0.4, 0.8, -6.0), new Vector3d(0, -0.1, 1), 45),
      Sources = new LinkedList<ILightSource>(new ILightSource[]
      {
        new AmbientLightSource(0.6), new PointLightSource(new Vector3d(-4, 5, -4), 1.2),
      }),
    };
  }

  static Rgb8Image Render(Func<ISolid> ball, AccelMode mode) =>
    Rgb8Image.FromFloatImage(RenderHelper.Render(Scene(ball), mode, 160, 120, threads: 2));

  public static TheoryData<string> StudentSpheres => new() { "normal in the hit", "normal in completion", "tangents only" };

  static ISolid Student(string kind) => kind switch
  {
    "normal in the hit" => new NormalInHitSphere(),
    "normal in completion" => new NormalLocalSphere(),
    _ => new TangentSphere(),
  };

  [Theory]
  [MemberData(nameof(StudentSpheres))]
  public void A_student_sphere_completed_by_the_contract_looks_like_the_library_Sphere(string kind)
  {
    foreach (AccelMode mode in new[] { AccelMode.None, AccelMode.Bvh })
    {
      Rgb8Image library = Render(() => new Sphere(), mode);
      Rgb8Image student = Render(() => Student(kind), mode);
      double psnr = ImageComparison.Psnr(student, library);
      output.WriteLine($"{kind} ({mode}): PSNR {psnr:F2} dB against Sphere");
      if (psnr < 40.0)
      {
        string diff = Path.Combine(Path.GetTempPath(), $"grcis-contract-{kind.Replace(' ', '-')}-{mode}-diff.png");
        ImageComparison.SaveDifference(diff, student, library);
        Assert.Fail($"{kind} ({mode}): PSNR {psnr:F2} dB < 40 dB; difference: {diff}");
      }
    }
  }

  [Theory]
  [MemberData(nameof(StudentSpheres))]
  public void The_faithful_and_the_fast_path_complete_a_student_sphere_alike(string kind)
  {
    Rgb8Image none = Render(() => Student(kind), AccelMode.None);
    Rgb8Image bvh = Render(() => Student(kind), AccelMode.Bvh);
    Assert.True(none.ContentEquals(bvh), $"{kind}: max channel difference {ImageComparison.MaxChannelDifference(none, bvh)}");
  }
}
