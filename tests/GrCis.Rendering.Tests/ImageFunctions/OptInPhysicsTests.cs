using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.ImageFunctions;

public class OptInPhysicsTests
{
  sealed class Probe : RayTracing
  {
    public Probe(IRayScene scene) : base(scene) { }

    public double Transmittance(Vector3d p0, Vector3d dir) => ShadowTransmittance(p0, dir);
  }

  static (DefaultRayScene scene, Sphere ball) SceneWithBall(double kt)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    var ball = new Sphere();
    ball.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 1, 1, 1 }, 0.1, 0.5, 0.4, 16) { Kt = kt });
    root.InsertChild(ball, Matrix4d.CreateTranslation(0, 5, 0));
    return (new DefaultRayScene { Intersectable = root }, ball);
  }

  [Fact]
  public void Glass_ball_between_point_and_light_passes_its_kt()
  {
    (DefaultRayScene scene, _) = SceneWithBall(0.6);
    Assert.Equal(0.6, new Probe(scene).Transmittance(Vector3d.Zero, new Vector3d(0, 10, 0)), 12);
  }

  [Fact]
  public void Opaque_ball_blocks_completely()
  {
    (DefaultRayScene scene, _) = SceneWithBall(0.0);
    Assert.Equal(0.0, new Probe(scene).Transmittance(Vector3d.Zero, new Vector3d(0, 10, 0)));
  }

  [Fact]
  public void Ball_beyond_the_light_does_not_shadow()
  {
    (DefaultRayScene scene, _) = SceneWithBall(0.0);
    Assert.Equal(1.0, new Probe(scene).Transmittance(Vector3d.Zero, new Vector3d(0, 2, 0)));
  }

  [Fact]
  public void No_shadow_solids_are_ignored()
  {
    (DefaultRayScene scene, Sphere ball) = SceneWithBall(0.0);
    ball.SetAttribute(PropertyName.NO_SHADOW, true);
    Assert.Equal(1.0, new Probe(scene).Transmittance(Vector3d.Zero, new Vector3d(0, 10, 0)));
  }

  [Fact]
  public void Schlick_reflectance_is_r0_head_on_and_one_at_grazing()
  {
    Assert.Equal(0.04, RayTracing.SchlickReflectance(1.0, 1.5), 12);
    Assert.Equal(1.0, RayTracing.SchlickReflectance(0.0, 1.5), 12);
  }

  static double[] RenderCentre(bool transparentShadows, bool fresnel)
  {
    // A glass ball above a white floor, lit from straight above; the camera looks down at the floor
    // under the ball (through nothing): only the shadow differs between the switches.
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 1, 1, 1 }, 0.1, 0.8, 0.0, 16, 0.0));
    var ball = new Sphere();
    ball.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 1, 1, 1 }, 0.0, 0.0, 0.1, 16) { Kt = 0.8, n = 1.5 });
    root.InsertChild(ball, Matrix4d.Scale(0.5) * Matrix4d.CreateTranslation(0, 2, 0));
    root.InsertChild(new Plane(), Matrix4d.RotateX(-System.Math.PI / 2));
    var scene = new DefaultRayScene
    {
      Intersectable = root,
      BackgroundColor = new double[] { 0, 0, 0 },
      Camera = new StaticCamera(new Vector3d(3, 1, 0), new Vector3d(-3, -1, 0), 10) { Width = 3, Height = 3 },
      Sources = new System.Collections.Generic.List<ILightSource> { new PointLightSource(new Vector3d(0, 10, 0), 1.0) },
    };
    var rt = new RayTracing(scene) { TransparentShadows = transparentShadows, FresnelRefraction = fresnel };
    double[] c = new double[3];
    rt.GetSample(1.5, 1.5, c);
    return c;
  }

  [Fact]
  public void Transparent_shadows_brighten_the_floor_under_glass_and_are_off_by_default()
  {
    double dark = RenderCentre(false, false)[0];
    double lit = RenderCentre(true, false)[0];
    Assert.Equal(0.0, dark, 9);   // GrCis: any occluder blocks the only light
    Assert.Equal(0.8 * 0.8, lit, 9);   // Kt × kd (light straight above the floor)
  }

  [Fact]
  public void Fresnel_refraction_darkens_what_is_seen_through_glass()
  {
    var ball = new Sphere();
    var mat = new PhongMaterial(new double[] { 0, 0, 0 }, 0.0, 0.0, 0.0, 1, 0.0) { Kt = 1.0, n = 1.5 };
    ball.SetAttribute(PropertyName.MATERIAL, mat);
    var scene = new DefaultRayScene
    {
      Intersectable = ball,
      BackgroundColor = new double[] { 1, 1, 1 },
      Camera = new StaticCamera(new Vector3d(0, 0, -5), Vector3d.UnitZ, 10) { Width = 3, Height = 3 },
    };
    double[] plain = new double[3], fresnel = new double[3];
    new RayTracing(scene).GetSample(1.5, 1.5, plain);
    new RayTracing(scene) { FresnelRefraction = true }.GetSample(1.5, 1.5, fresnel);
    Assert.Equal(1.0, plain[0], 9);
    // Two interfaces head on, each passing 1 − 0.04.
    Assert.Equal(0.96 * 0.96, fresnel[0], 6);
  }
}
