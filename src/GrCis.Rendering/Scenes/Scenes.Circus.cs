using System;
using OpenTK.Mathematics;

namespace Rendering;

public partial class Scenes
{
  /// <summary>CSG circus (by A. Hanka, 2012): a clown head and tests of every set operation.</summary>
  public static void Circus(IRayScene sc)
  {
    CSGInnerNode root = Root(sc, new PhongMaterial(new[] { 0.5, 0.5, 0.5 }, 0.2, 0.8, 0.1, 16));
    sc.BackgroundColor = new[] { 0.5, 0.7, 0.6 };
    sc.Camera = new StaticCamera(new Vector3d(0.0, 0.0, -11.0), new Vector3d(0.0, 0.0, 1.0), 60.0);
    Lights(sc, 1.0, new Vector3d(-5.0, 3.0, -3.0), 1.2);

    // Note the order: translation first, then rotation and scale (about the world origin).
    root.InsertChild(head(), Matrix4d.CreateTranslation(-6.0, 1.5, 0.0) * Matrix4d.RotateY(Math.PI / 10) * Matrix4d.Scale(0.7));
    root.InsertChild(test6Spheres(SetOperation.Difference), Matrix4d.CreateTranslation(0.0, 1.5, 0.0) * Matrix4d.Scale(0.7));
    root.InsertChild(testXor2(),
      Matrix4d.CreateTranslation(6.0, 1.5, 0.0) * Matrix4d.RotateX(Math.PI / 3) * Matrix4d.RotateY(Math.PI / 4) * Matrix4d.Scale(0.6));
    root.InsertChild(testWithCylindersXor(), Matrix4d.CreateTranslation(-5.0, -2.5, 0.0) * Matrix4d.Scale(0.7));
    root.InsertChild(testWithCylinders(SetOperation.Xor), Matrix4d.CreateTranslation(0.0, -2.5, 0.0) * Matrix4d.Scale(0.7));
    root.InsertChild(test2Spheres(SetOperation.Intersection), Matrix4d.CreateTranslation(4.0, -1.5, 0.0));
  }
}
