using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Interactive.Tests;

/// <summary>Small scenes whose answers are known.</summary>
internal static class TestScenes
{
  public static readonly double[] Background = { 0.1, 0.2, 0.3 };

  /// <summary>A mirror (or glass) sphere of radius 1 at the origin above a checkered floor y = −1; camera at z = −5 looking +z.</summary>
  public static IRayScene SphereOnPlane(bool glass = false)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.5, 0.5, 0.5 }, 0.1, 0.6, 0.3, 16));

    var sphere = new Sphere();
    var m = glass
      ? new PhongMaterial(new[] { 0.0, 0.2, 0.1 }, 0.05, 0.05, 0.1, 128) { Kt = 0.9, n = 1.5 }
      : new PhongMaterial(new[] { 1.0, 1.0, 0.8 }, 0.05, 0.1, 0.85, 128);
    sphere.SetAttribute(PropertyName.MATERIAL, m);
    root.InsertChild(sphere, Matrix4d.Identity);

    var plane = new Plane();
    plane.SetAttribute(PropertyName.COLOR, new[] { 0.6, 0.1, 0.1 });
    plane.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(1.0, 1.0, new[] { 1.0, 1.0, 1.0 }));
    root.InsertChild(plane, Matrix4d.CreateRotationX(-Math.PI / 2) * Matrix4d.CreateTranslation(0, -1, 0));

    return new DefaultRayScene
    {
      Intersectable = root,
      BackgroundColor = (double[])Background.Clone(),
      Camera = new StaticCamera(new Vector3d(0, 0, -5), Vector3d.UnitZ, 40.0),
      Sources = new LinkedList<ILightSource>(new ILightSource[]
      {
        new AmbientLightSource(0.8),
        new PointLightSource(new Vector3d(-5, 5, -5), 1.0),
      }),
    };
  }

  /// <summary>The plane z = <paramref name="z"/> facing a camera at the origin that looks along +z.</summary>
  public static IRayScene PlaneAt(double z)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    var plane = new Plane();
    plane.SetAttribute(PropertyName.COLOR, new[] { 0.2, 0.7, 0.2 });
    // The plane's front (+z) mirrored towards the camera, exactly (a rotation by π would leave 1e-16 in the normal).
    root.InsertChild(plane, Matrix4d.Scale(1.0, 1.0, -1.0) * Matrix4d.CreateTranslation(0, 0, z));
    return new DefaultRayScene
    {
      Intersectable = root,
      BackgroundColor = (double[])Background.Clone(),
      Camera = new StaticCamera(Vector3d.Zero, Vector3d.UnitZ, 60.0),
      Sources = new LinkedList<ILightSource>(new ILightSource[] { new AmbientLightSource(0.5), new PointLightSource(new Vector3d(0, 0, -1), 1.0) }),
    };
  }
}
