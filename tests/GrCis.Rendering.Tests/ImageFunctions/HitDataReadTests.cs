using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Rendering.Execution;
using Rendering.Imaging;
using Rendering.Observation;

namespace GrCis.Rendering.Tests.ImageFunctions;

/// <summary>
/// What an image function reads from hits is decided from what its class overrides, not from its exact type:
/// a subclass that overrides nothing that sees a hit keeps the cheaper surface-only hits; one that overrides
/// shade gets full hits unless it declares otherwise.
/// </summary>
public class HitDataReadTests
{
  sealed class Named : RayTracing
  {
    public Named(IRayScene? sc = null) : base(sc) { }
    public string Label = "mine";
    public HitData Reads => HitDataRead;
  }

  class Shading : RayTracing
  {
    public Shading(IRayScene? sc = null) : base(sc) { }
    public override long shade(int depth, double importance, ref Vector3d p0, ref Vector3d p1, double[] color) =>
      base.shade(depth, importance, ref p0, ref p1, color);
    public HitData Reads => HitDataRead;
  }

  sealed class ShadingOfShading : Shading
  {
  }

  sealed class DeclaresSurface : Shading
  {
    protected override HitData HitDataRead => HitData.Surface;
    public HitData DeclaredReads => HitDataRead;
  }

  sealed class Casting : RayCasting
  {
    protected override Intersection? FirstHit(Vector3d p0, Vector3d p1) => base.FirstHit(p0, p1);
    public HitData Reads => HitDataRead;
  }

  [Fact]
  public void Overriding_a_method_that_sees_hits_decides_not_the_type()
  {
    Assert.Equal(HitData.Surface, new Named().Reads);
    Assert.Equal(HitData.All, new Shading().Reads);
    Assert.Equal(HitData.All, new ShadingOfShading().Reads);
    Assert.Equal(HitData.Surface, new DeclaresSurface().DeclaredReads);
    Assert.Equal(HitData.All, new Casting().Reads);
  }

  /// <summary>Counts sphere hits that arrive without their local frame (tangents left zero).</summary>
  sealed class FrameWatcher : RayObserver
  {
    public int SphereHits, WithoutFrame;

    public override void EndRay(RayKind kind, int depth, in Vector3d origin, in Vector3d direction, Intersection? hit)
    {
      if (hit?.Solid is not Sphere)
        return;
      SphereHits++;
      if (hit.TangentU == Vector3d.Zero && hit.TangentV == Vector3d.Zero)
        WithoutFrame++;
    }
  }

  static IRayScene Balls()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.8, 0.5, 0.2 }, 0.1, 0.6, 0.3, 16));
    root.InsertChild(new Sphere(), Matrix4d.CreateTranslation(-1.2, 0, 0));
    root.InsertChild(new Sphere(), Matrix4d.CreateTranslation(1.2, 0, 0));
    return new DefaultRayScene
    {
      Intersectable = root,
      BackgroundColor = new[] { 0.1, 0.2, 0.3 },
      Camera = new StaticCamera(new Vector3d(0, 0, -6), Vector3d.UnitZ, 50.0),
      Sources = new LinkedList<ILightSource>(new ILightSource[] { new AmbientLightSource(0.5), new PointLightSource(new Vector3d(-5, 5, -5), 1.0) }),
    };
  }

  static (FloatImage Image, FrameWatcher Watcher) Render(RayTracing f, IRayScene scene)
  {
    var watcher = new FrameWatcher();
    FloatImage image = TileRenderer.Render(scene, f, new SimpleImageSynthesizer { Width = 48, Height = 36 },
      new RenderOptions { Threads = 1 }, null, default, new RenderContext { Observer = watcher });
    return (image, watcher);
  }

  [Fact]
  public void A_subclass_that_overrides_nothing_that_sees_hits_keeps_surface_only_hits_and_the_same_picture()
  {
    IRayScene scene = Balls();
    (FloatImage plain, FrameWatcher plainHits) = Render(new RayTracing(scene), scene);
    (FloatImage named, FrameWatcher namedHits) = Render(new Named(scene), scene);
    (FloatImage shading, FrameWatcher shadingHits) = Render(new Shading(scene), scene);

    Assert.Equal(plain.Data, named.Data);
    Assert.Equal(plain.Data, shading.Data);
    Assert.True(plainHits.SphereHits > 100);
    Assert.Equal(plainHits.SphereHits, plainHits.WithoutFrame);   // the library's own tracer: surface only
    Assert.Equal(namedHits.SphereHits, namedHits.WithoutFrame);   // so is a subclass that only adds a field
    Assert.Equal(0, shadingHits.WithoutFrame);                    // an overridden shade sees complete hits
  }
}
