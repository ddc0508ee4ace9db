using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.ImageFunctions;

/// <summary>The Cornell box of the shared benchmark specification, built in code (scripts/CornellBox.cs builds the same through a script).</summary>
internal static class CornellScene
{
  public static IRayScene Create(bool diffuse)
  {
    static PhongMaterial Lambert(double r, double g, double b) => new(new[] { r, g, b }, 0.0, 1.0, 0.0, 1);
    PhongMaterial white = Lambert(0.73, 0.73, 0.73);
    var top = new CSGInnerNode(SetOperation.Union);
    top.SetAttribute(PropertyName.MATERIAL, white);
    var root = new CSGInnerNode(SetOperation.Union);
    top.InsertChild(root, Matrix4d.Scale(-1.0, 1.0, 1.0));   // the specification is right-handed

    void Wall(double x0, double x1, double y0, double y1, Matrix4d place, PhongMaterial m)
    {
      var wall = new Plane(x0, x1, y0, y1);
      wall.SetAttribute(PropertyName.MATERIAL, m);
      root.InsertChild(wall, place);
    }
    Wall(-1, 1, -1, 1, Matrix4d.RotateX(-MathHelper.PiOver2), white);
    Wall(-1, 1, 0, 2, Matrix4d.CreateTranslation(0, 0, -1), white);
    Wall(-1, 1, 0, 2, Matrix4d.RotateY(MathHelper.PiOver2) * Matrix4d.CreateTranslation(-1, 0, 0), Lambert(0.65, 0.05, 0.05));
    Wall(-1, 1, 0, 2, Matrix4d.RotateY(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(1, 0, 0), Lambert(0.12, 0.45, 0.15));
    Matrix4d ceiling = Matrix4d.RotateX(MathHelper.PiOver2) * Matrix4d.CreateTranslation(0, 2, 0);
    Wall(-1, -0.25, -1, 1, ceiling, white);
    Wall(0.25, 1, -1, 1, ceiling, white);
    Wall(-0.25, 0.25, -1, -0.2, ceiling, white);
    Wall(-0.25, 0.25, 0.2, 1, ceiling, white);
    Wall(-0.25, 0.25, -0.2, 0.2, ceiling, new PhongMaterial(new[] { 0.0, 0.0, 0.0 }, 0.0, 0.0, 0.0, 1) { Emission = new[] { 15.0, 15.0, 15.0 } });

    PhongMaterial a = white, b = white;
    if (!diffuse)
    {
      a = new PhongMaterial(new[] { 1.0, 1.0, 1.0 }, 0.0, 0.0, 1.0, 1000000);
      b = new PhongMaterial(new[] { 1.0, 1.0, 1.0 }, 0.0, 0.0, 0.0, 1) { Kt = 1.0, n = 1.5 };
    }
    var sa = new Sphere();
    sa.SetAttribute(PropertyName.MATERIAL, a);
    root.InsertChild(sa, Matrix4d.Scale(0.4) * Matrix4d.CreateTranslation(-0.45, 0.4, -0.35));
    var sb = new Sphere();
    sb.SetAttribute(PropertyName.MATERIAL, b);
    root.InsertChild(sb, Matrix4d.Scale(0.4) * Matrix4d.CreateTranslation(0.45, 0.4, 0.35));

    return new DefaultRayScene
    {
      Intersectable = top,
      BackgroundColor = new[] { 0.0, 0.0, 0.0 },
      Camera = new StaticCamera(new Vector3d(0.0, 1.0, 3.7), new Vector3d(0.0, 0.0, -1.0), 40.0),
      Sources = new LinkedList<ILightSource>(),
    };
  }
}
