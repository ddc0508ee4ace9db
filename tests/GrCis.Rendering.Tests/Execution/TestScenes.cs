using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Execution;

/// <summary>Small scenes for execution tests: a glossy, transparent ball over a checkered ground ball.</summary>
internal static class TestScenes
{
  public static IRayScene BallOnGround(bool areaLight)
  {
    var sc = new DefaultRayScene();
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.8, 0.7, 0.2 }, 0.1, 0.6, 0.3, 32));
    sc.Intersectable = root;
    sc.BackgroundColor = new[] { 0.1, 0.2, 0.3 };
    sc.Camera = new StaticCamera(new Vector3d(0.0, 0.6, -4.0), new Vector3d(0.0, -0.15, 1.0), 50.0);

    var ball = new TestBall();
    ball.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.6, 0.6, 0.9 }, 0.1, 0.5, 0.5, 64) { Kt = 0.5, n = 1.5 });
    root.InsertChild(ball, Matrix4d.Identity);

    var ground = new TestBall { Radius = 100.0 };
    ground.AddTexture(new CheckerTexture(40.0, 40.0, new[] { 0.9, 0.9, 0.9 }));
    root.InsertChild(ground, Matrix4d.CreateTranslation(0.0, -101.0, 0.0));

    ILightSource light = areaLight
      ? new RectangleLightSource(new Vector3d(-3.0, 4.0, -2.0), new Vector3d(2.0, 0.0, 0.0), new Vector3d(0.0, 0.0, 2.0), 1.2)
      : new PointLightSource(new Vector3d(-3.0, 4.0, -2.0), 1.2);
    sc.Sources = new List<ILightSource> { new AmbientLightSource(0.8), light };
    return sc;
  }
}
