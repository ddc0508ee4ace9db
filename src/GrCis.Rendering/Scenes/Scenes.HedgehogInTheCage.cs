using System;
using OpenTK.Mathematics;

namespace Rendering;

public partial class Scenes
{
  /// <summary>Hedgehog in the cage (by M. Wirth, 2012): spheres stretched into cylinders and spines, all CSG.</summary>
  public static void HedgehogInTheCage(IRayScene sc)
  {
    CSGInnerNode root = Root(sc, new PhongMaterial(new[] { 0.5, 0.5, 0.5 }, 0.2, 0.6, 0.2, 16));
    sc.BackgroundColor = new[] { 0.0, 0.05, 0.05 };
    sc.Camera = new StaticCamera(new Vector3d(0.0, 2.0, -7.0), new Vector3d(0.0, -0.32, 1.0), 40.0);
    Lights(sc, 0.8, new Vector3d(-8.0, 5.0, -3.0), 1.0);

    // Cage: a tube (outer minus inner) with a hole through the top and three pairs of windows.
    var cage = new CSGInnerNode(SetOperation.Difference);
    cage.SetAttribute(PropertyName.COLOR, new[] { 0.70, 0.93, 0.20 });
    cage.InsertChild(Stretched(Matrix4d.Scale(1.0, 1000.0, 1.0), Matrix4d.Scale(1000.0, 1.5, 1000.0)), Matrix4d.Identity);
    cage.InsertChild(Stretched(Matrix4d.Scale(1.0, 1000.0, 1.0), Matrix4d.Scale(1000.0, 1.5, 1000.0)), Matrix4d.Scale(0.9));
    cage.InsertChild(new Sphere(), Matrix4d.Scale(0.5, 1000.0, 0.5));
    cage.InsertChild(Stretched(Matrix4d.Scale(1000.0, 1.1, 1000.0), Matrix4d.Scale(0.4, 1000.0, 1000.0)), Matrix4d.Identity);
    cage.InsertChild(Stretched(Matrix4d.Scale(1000.0, 1.1, 1000.0), Matrix4d.Scale(0.4, 1000.0, 1000.0)), Matrix4d.RotateY(Math.PI / 3));
    cage.InsertChild(Stretched(Matrix4d.Scale(1000.0, 1.1, 1000.0), Matrix4d.Scale(0.4, 1000.0, 1000.0)), Matrix4d.RotateY(Math.PI / -3));

    // Hedgehog: a ball with six spines (thin needles clipped by shifted spheres).
    var hedgehog = new CSGInnerNode(SetOperation.Union);
    hedgehog.SetAttribute(PropertyName.COLOR, new[] { 0.4, 0.05, 0.05 });
    hedgehog.InsertChild(new Sphere(), Matrix4d.Scale(0.48));
    Matrix4d needle = Matrix4d.Scale(0.06, 1000.0, 0.06);
    Matrix4d tilt = Matrix4d.RotateX(Math.PI / -3);
    hedgehog.InsertChild(Stretched(needle, Matrix4d.Scale(1.2)), Matrix4d.Identity);
    hedgehog.InsertChild(Stretched(needle, Spine(0.1)), tilt);
    hedgehog.InsertChild(Stretched(needle, Spine(-0.25)), tilt * Matrix4d.RotateY(Math.PI * -0.4));
    hedgehog.InsertChild(Stretched(needle, Spine(0.2)), tilt * Matrix4d.RotateY(Math.PI * -0.8));
    hedgehog.InsertChild(Stretched(needle, Spine(-0.2)), tilt * Matrix4d.RotateY(Math.PI * 0.4));
    hedgehog.InsertChild(Stretched(needle, Spine(-0.25)), tilt * Matrix4d.RotateY(Math.PI * 0.8));

    var all = new CSGInnerNode(SetOperation.Union);
    all.InsertChild(cage, Matrix4d.RotateY(0.25));
    all.InsertChild(hedgehog, Matrix4d.Rotate(new Vector3d(0.0, 1.0, 1.0), 0.1) * Matrix4d.CreateTranslation(0.0, -0.1, 0.0));
    root.InsertChild(all, Matrix4d.RotateZ(0.1));

    static Matrix4d Spine(double shift) => Matrix4d.Scale(1.2) * Matrix4d.CreateTranslation(0.0, shift, 0.0);
  }

  /// <summary>Intersection of two transformed unit spheres.</summary>
  static CSGInnerNode Stretched(Matrix4d first, Matrix4d second)
  {
    var node = new CSGInnerNode(SetOperation.Intersection);
    node.InsertChild(new Sphere(), first);
    node.InsertChild(new Sphere(), second);
    return node;
  }
}
