using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Testing;

/// <summary>
/// Scenes for the differential tests and the benchmarks, built from the stand-in solids until the
/// classic <c>Scenes</c> registry and the real solids are merged.
/// </summary>
public static class TestScenes
{
  public delegate IRayScene Builder();

  /// <summary>All named scenes of the differential test.</summary>
  public static readonly IReadOnlyList<(string Name, Builder Build)> All = new (string, Builder)[]
  {
    ("five-balls", FiveBalls),
    ("two-spheres-glass", TwoSpheresGlass),
    ("csg-mix", CsgMix),
    ("overlapping-glass", OverlappingGlass),
    ("camera-inside", CameraInside),
    ("below-plane", BelowPlane),
    ("single-sphere", SingleSphere),
    ("single-difference", SingleDifference),
    ("grcis-flake-3", () => GrCisFlake(3)),
    ("flake9-2", () => Flake9(2)),
  };

  static DefaultRayScene Base(CSGInnerNode root, Vector3d camPos, Vector3d camDir, double angle, params ILightSource[] lights)
  {
    var scene = new DefaultRayScene
    {
      Intersectable = root,
      BackgroundColor = new[] { 0.0, 0.05, 0.07 },
      Camera = new StaticCamera(camPos, camDir, angle),
      Sources = new LinkedList<ILightSource>(lights),
    };
    return scene;
  }

  static CSGInnerNode Root(PhongMaterial m)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, m);
    return root;
  }

  static RefPlane Floor(double[] color, double checker)
  {
    var plane = new RefPlane();
    plane.SetAttribute(PropertyName.COLOR, color);
    plane.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(checker, checker, new[] { 1.0, 1.0, 1.0 }));
    return plane;
  }

  static Matrix4d FloorMatrix => Matrix4d.RotateX(-Math.PI / 2) * Matrix4d.CreateTranslation(0, -1, 0);

  public static IRayScene FiveBalls()
  {
    CSGInnerNode root = Root(new PhongMaterial(new[] { 0.5, 0.5, 0.5 }, 0.1, 0.6, 0.3, 16));
    double[][] colors = { new[] { 1.0, 0.6, 0.0 }, new[] { 0.2, 0.9, 0.5 }, new[] { 0.1, 0.3, 1.0 }, new[] { 1.0, 0.2, 0.2 }, new[] { 0.1, 0.4, 0.0 } };
    double[] x = { 0.0, -2.2, -4.4, 2.2, 4.4 };
    for (int i = 0; i < 5; i++)
    {
      var s = new RefSphere();
      s.SetAttribute(PropertyName.COLOR, colors[i]);
      if (i == 4)
        s.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(80.0, 40.0, new[] { 1.0, 0.8, 0.2 }));
      root.InsertChild(s, Matrix4d.CreateTranslation(x[i], 0, 0));
    }
    return Base(root, new Vector3d(0, 0, -10), new Vector3d(0, 0, 1), 60,
      new AmbientLightSource(0.8), new PointLightSource(new Vector3d(-5, 3, -3), 1.0));
  }

  public static IRayScene TwoSpheresGlass()
  {
    CSGInnerNode root = Root(new PhongMaterial(new[] { 1.0, 0.8, 0.1 }, 0.1, 0.6, 0.4, 128));
    var glass = new PhongMaterial(new[] { 0.0, 0.2, 0.1 }, 0.05, 0.05, 0.1, 128) { n = 1.6, Kt = 0.9 };
    var s = new RefSphere();
    s.SetAttribute(PropertyName.MATERIAL, glass);
    root.InsertChild(s, Matrix4d.Identity);
    root.InsertChild(new RefSphere(), Matrix4d.Scale(1.2) * Matrix4d.CreateTranslation(1.5, 0.2, 2.4));
    root.InsertChild(Floor(new[] { 0.3, 0.0, 0.0 }, 0.6), FloorMatrix);
    return Base(root, new Vector3d(0.7, 0.5, -5), new Vector3d(0, -0.18, 1), 50,
      new AmbientLightSource(0.8), new PointLightSource(new Vector3d(-5, 4, -3), 1.2));
  }

  /// <summary>Non-union CSG leaves, nested unions with transforms, a script solid, a NO_SHADOW solid, cubes.</summary>
  public static IRayScene CsgMix()
  {
    CSGInnerNode root = Root(new PhongMaterial(new[] { 0.5, 0.5, 0.5 }, 0.2, 0.7, 0.1, 16));

    var diff = new CSGInnerNode(SetOperation.Difference);
    diff.SetAttribute(PropertyName.COLOR, new[] { 0.2, 0.2, 0.8 });
    diff.InsertChild(new RefSphere(), Matrix4d.Identity);
    var hole = new RefCube();
    hole.SetAttribute(PropertyName.COLOR, new[] { 1.0, 1.0, 1.0 });
    diff.InsertChild(hole, Matrix4d.CreateTranslation(-0.5, -0.5, -1.5) * Matrix4d.Scale(0.8));
    root.InsertChild(diff, Matrix4d.Scale(1.6, 1, 1) * Matrix4d.RotateY(Math.PI / 8) * Matrix4d.CreateTranslation(3.0, -1.0, 0));

    var isect = new CSGInnerNode(SetOperation.Intersection);
    isect.SetAttribute(PropertyName.COLOR, new[] { 0.9, 0.3, 0.1 });
    isect.InsertChild(new RefCube(), Matrix4d.CreateTranslation(-0.5, -0.5, -0.5) * Matrix4d.Scale(1.6));
    isect.InsertChild(new RefSphere(), Matrix4d.Identity);
    root.InsertChild(isect, Matrix4d.RotateX(0.4) * Matrix4d.CreateTranslation(-3.0, 1.0, 1.0));

    var group = new CSGInnerNode(SetOperation.Union);
    group.SetAttribute(PropertyName.COLOR, new[] { 0.1, 0.8, 0.2 });
    for (int i = 0; i < 5; i++)
    {
      var c = new RefCube();
      c.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(4, 4, new[] { 0.0, 0.0, 0.3 }));
      group.InsertChild(c, Matrix4d.CreateTranslation(-0.5, -0.5, -0.5) * Matrix4d.RotateZ(0.3 * i) * Matrix4d.CreateTranslation(0.9 * i - 2, 0.3 * i, 0.5 * i));
    }
    var inner = new CSGInnerNode(SetOperation.Union);
    inner.InsertChild(new RefSphere(), Matrix4d.Scale(0.5));
    group.InsertChild(inner, Matrix4d.CreateTranslation(0, 2, 0));
    root.InsertChild(group, Matrix4d.RotateY(0.3) * Matrix4d.CreateTranslation(0, -0.5, 2));

    var script = new ScriptSphere();
    script.SetAttribute(PropertyName.COLOR, new[] { 0.9, 0.9, 0.2 });
    root.InsertChild(script, Matrix4d.Scale(0.7) * Matrix4d.CreateTranslation(-1.5, -0.3, -1.5));

    var ghost = new RefSphere();
    ghost.SetAttribute(PropertyName.COLOR, new[] { 0.8, 0.8, 0.8 });
    ghost.SetAttribute(PropertyName.NO_SHADOW, true);
    root.InsertChild(ghost, Matrix4d.Scale(0.6) * Matrix4d.CreateTranslation(-1.0, 2.5, 0.0));

    var mirror = new RefCube();
    mirror.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 1.0, 1.0, 0.8 }, 0.0, 0.1, 0.9, 128));
    root.InsertChild(mirror, Matrix4d.Scale(6, 4, 0.2) * Matrix4d.CreateTranslation(-3, -1, 5));

    root.InsertChild(Floor(new[] { 0.6, 0.0, 0.0 }, 0.5), FloorMatrix);
    return Base(root, new Vector3d(0.7, 3.0, -10), new Vector3d(0, -0.3, 1), 50,
      new AmbientLightSource(0.8), new PointLightSource(new Vector3d(-5, 3, -3), 1.0), new PointLightSource(new Vector3d(5, 6, -4), 0.6));
  }

  /// <summary>Overlapping glass spheres in one union: rays inside them take the exact fallback.</summary>
  public static IRayScene OverlappingGlass()
  {
    CSGInnerNode root = Root(new PhongMaterial(new[] { 1.0, 0.8, 0.1 }, 0.1, 0.6, 0.4, 128));
    var glass = new PhongMaterial(new[] { 0.0, 0.2, 0.1 }, 0.05, 0.05, 0.1, 128) { n = 1.5, Kt = 0.9 };
    var blob = new CSGInnerNode(SetOperation.Union);
    blob.SetAttribute(PropertyName.MATERIAL, glass);
    blob.InsertChild(new RefSphere(), Matrix4d.CreateTranslation(-0.5, 0, 0));
    blob.InsertChild(new RefSphere(), Matrix4d.CreateTranslation(0.5, 0.2, 0.3));
    blob.InsertChild(new RefCube(), Matrix4d.CreateTranslation(-0.5, -0.5, -0.5) * Matrix4d.Scale(1.2) * Matrix4d.CreateTranslation(0, 0.8, 0));
    root.InsertChild(blob, Matrix4d.Identity);
    root.InsertChild(new RefSphere(), Matrix4d.Scale(0.8) * Matrix4d.CreateTranslation(1.5, -0.2, 2.4));
    root.InsertChild(Floor(new[] { 0.3, 0.0, 0.0 }, 0.6), FloorMatrix);
    return Base(root, new Vector3d(0.7, 0.5, -5), new Vector3d(0, -0.18, 1), 50,
      new AmbientLightSource(0.8), new PointLightSource(new Vector3d(-5, 4, -3), 1.2));
  }

  /// <summary>The camera sits inside a big sphere of the union: every primary ray starts inside.</summary>
  public static IRayScene CameraInside()
  {
    CSGInnerNode root = Root(new PhongMaterial(new[] { 0.6, 0.6, 0.9 }, 0.2, 0.6, 0.2, 16));
    root.InsertChild(new RefSphere(), Matrix4d.Scale(20));
    var ball = new RefSphere();
    ball.SetAttribute(PropertyName.COLOR, new[] { 1.0, 0.3, 0.1 });
    root.InsertChild(ball, Matrix4d.CreateTranslation(0, 0, 3));
    return Base(root, new Vector3d(0, 0, -5), new Vector3d(0, 0, 1), 60,
      new AmbientLightSource(0.5), new PointLightSource(new Vector3d(0, 5, -3), 1.0));
  }

  /// <summary>Camera below a floor plane looking up: the plane's half-space contains the camera.</summary>
  public static IRayScene BelowPlane()
  {
    CSGInnerNode root = Root(new PhongMaterial(new[] { 1.0, 0.6, 0.1 }, 0.1, 0.6, 0.4, 16));
    root.InsertChild(new RefSphere(), Matrix4d.CreateTranslation(0, 1, 0));
    root.InsertChild(new RefSphere(), Matrix4d.CreateTranslation(1.5, -3, 2));
    root.InsertChild(Floor(new[] { 0.0, 0.3, 0.0 }, 1.0), FloorMatrix);
    return Base(root, new Vector3d(0, -4, -6), new Vector3d(0, 0.5, 1), 60,
      new AmbientLightSource(0.5), new PointLightSource(new Vector3d(-3, 5, -3), 1.0));
  }

  /// <summary>The scene is one solid (no union): its raw list decides.</summary>
  public static IRayScene SingleSphere()
  {
    var s = new RefSphere();
    s.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.9, 0.5, 0.2 }, 0.1, 0.7, 0.3, 32));
    var scene = new DefaultRayScene
    {
      Intersectable = s,
      BackgroundColor = new[] { 0.0, 0.05, 0.07 },
      Camera = new StaticCamera(new Vector3d(0, 0, -4), new Vector3d(0, 0, 1), 50),
      Sources = new LinkedList<ILightSource>(new ILightSource[] { new AmbientLightSource(0.5), new PointLightSource(new Vector3d(-3, 3, -3), 1.0) }),
    };
    return scene;
  }

  public static IRayScene SingleDifference()
  {
    var diff = new CSGInnerNode(SetOperation.Difference);
    diff.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.2, 0.6, 0.9 }, 0.1, 0.7, 0.3, 32));
    diff.InsertChild(new RefCube(), Matrix4d.CreateTranslation(-0.5, -0.5, -0.5) * Matrix4d.Scale(2) * Matrix4d.RotateY(0.5) * Matrix4d.RotateX(0.4));
    diff.InsertChild(new RefSphere(), Matrix4d.Scale(1.3));
    var scene = new DefaultRayScene
    {
      Intersectable = diff,
      BackgroundColor = new[] { 0.0, 0.05, 0.07 },
      Camera = new StaticCamera(new Vector3d(0, 0, -5), new Vector3d(0, 0, 1), 50),
      Sources = new LinkedList<ILightSource>(new ILightSource[] { new AmbientLightSource(0.5), new PointLightSource(new Vector3d(-3, 3, -3), 1.0) }),
    };
    return scene;
  }

  /// <summary>GrCis's own flake (fact sheet §1.6): 7 children of scale 0.4 per level, nested unions.</summary>
  public static IRayScene GrCisFlake(int depth)
  {
    CSGInnerNode root = Root(new PhongMaterial(new[] { 1.0, 0.8, 0.1 }, 0.1, 0.6, 0.4, 128));
    ISceneNode sf = GrCisFlakeNode(depth, 0.4);
    sf.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 1.0, 0.6, 0.1 }, 0.1, 0.85, 0.05, 16));
    root.InsertChild(sf, Matrix4d.Identity);
    root.InsertChild(Floor(new[] { 0.3, 0.0, 0.0 }, 0.6), FloorMatrix);
    return Base(root, new Vector3d(1.6, 2.2, -7), new Vector3d(-0.12, -0.3, 1), 50,
      new AmbientLightSource(0.8), new PointLightSource(new Vector3d(-5, 4, -3), 1.2));
  }

  static ISceneNode GrCisFlakeNode(int depth, double coef)
  {
    Matrix4d mat = Matrix4d.Scale(coef) * Matrix4d.CreateTranslation(0, 1 + coef, 0);
    double a = 2.0 * Math.Atan2(1.0, Math.Sqrt(2.0));
    Matrix4d m1 = mat * Matrix4d.RotateX(a), m2 = mat * Matrix4d.RotateX(a + Math.PI);
    var node = new CSGInnerNode(SetOperation.Union);
    node.InsertChild(new RefSphere(), Matrix4d.Identity);
    if (--depth > 0)
    {
      Matrix4d[] ms =
      {
        mat, m1, m2, m1 * Matrix4d.RotateY(2 * Math.PI / 3), m2 * Matrix4d.RotateY(2 * Math.PI / 3),
        m1 * Matrix4d.RotateY(4 * Math.PI / 3), m2 * Matrix4d.RotateY(4 * Math.PI / 3),
      };
      foreach (Matrix4d m in ms)
        node.InsertChild(GrCisFlakeNode(depth, coef), m);
    }
    return node;
  }

  /// <summary>
  /// The POV-Ray peer flake (shared/bench/povray/sphereflake.pov): 9 children of radius 1/3 per level,
  /// depth 4 = 7,381 spheres, as nested unions with one transform per level (GrCis style).
  /// </summary>
  public static IRayScene Flake9(int depth = 4)
  {
    CSGInnerNode root = Root(new PhongMaterial(new[] { 1.0, 0.8, 0.1 }, 0.1, 0.6, 0.4, 128));
    ISceneNode sf = Flake9Node(depth, global::Rendering.Scenes.Flake9Transforms());
    sf.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 1.0, 0.6, 0.1 }, 0.1, 0.6, 0.3, 16));
    root.InsertChild(sf, Matrix4d.Identity);
    root.InsertChild(Floor(new[] { 0.3, 0.0, 0.0 }, 0.6), FloorMatrix);
    return Base(root, new Vector3d(1.6, 2.2, -7), new Vector3d(-0.12, -0.3, 1), 50,
      new AmbientLightSource(0.8), new PointLightSource(new Vector3d(-5, 4, -3), 1.2));
  }

  static ISceneNode Flake9Node(int depth, Matrix4d[] children)
  {
    var node = new CSGInnerNode(SetOperation.Union);
    node.InsertChild(new RefSphere(), Matrix4d.Identity);
    if (depth > 0)
      foreach (Matrix4d m in children)
        node.InsertChild(Flake9Node(depth - 1, children), m);
    return node;
  }
}
