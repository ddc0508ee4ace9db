using System;
using OpenTK.Mathematics;

namespace Rendering;

public partial class Scenes
{
  /// <summary>Six national flags in artistic style (by J. Vlcek, 2012), each built with a different CSG operation.</summary>
  public static void Flags(IRayScene sc)
  {
    CSGInnerNode flags = Root(sc, new PhongMaterial(new[] { 0.5, 0.5, 0.5 }, 0.2, 0.7, 0.1, 16));
    sc.BackgroundColor = new[] { 0.0, 0.05, 0.05 };
    sc.Camera = new StaticCamera(new Vector3d(0.0, 0.0, -10.0), new Vector3d(0.0, 0.0, 1.0), 60.0);
    sc.Sources = new System.Collections.Generic.LinkedList<ILightSource>(new ILightSource[]
    {
      new AmbientLightSource(0.8),
      new PointLightSource(new Vector3d(-5.0, 3.0, -3.0), 1.0),
      new PointLightSource(new Vector3d(5.0, 3.0, -3.0), 1.0),
    });

    double[] white = { 1.0, 1.0, 1.0 };
    double[] red = { 1.0, 0.0, 0.0 };
    double[] blue = { 0.0, 0.0, 1.0 };
    double[] darkRed = { 0.3, 0.0, 0.0 };
    Matrix4d centre = Matrix4d.CreateTranslation(-0.5, -0.5, -0.5);

    // Latvia (intersection with a xor).
    var latvia = new CSGInnerNode(SetOperation.Intersection);
    latvia.InsertChild(ColoredCube(darkRed), Matrix4d.Scale(4.0, 2.0, 0.4) * Matrix4d.CreateTranslation(-2.0, -1.0, 0.0));
    var latviaFlag = new CSGInnerNode(SetOperation.Xor);
    latviaFlag.InsertChild(ColoredCube(darkRed), centre * Matrix4d.Scale(4.0, 2.0, 2.0));
    latviaFlag.InsertChild(ColoredCube(white), centre * Matrix4d.Scale(4.2, 0.5, 0.5));
    latvia.InsertChild(latviaFlag, Matrix4d.Identity);
    flags.InsertChild(latvia, Matrix4d.Scale(0.7) * Matrix4d.CreateRotationX(Math.PI / 8) * Matrix4d.CreateTranslation(-3.5, 1.5, 0.0));

    // Czech Republic (difference of spheres).
    var czech = new CSGInnerNode(SetOperation.Difference);
    czech.InsertChild(ColoredSphere(new[] { 0.2, 0.2, 0.2 }), Matrix4d.Identity);
    czech.InsertChild(ColoredSphere(white), Matrix4d.CreateTranslation(0.0, 0.8, -1.0));
    czech.InsertChild(ColoredSphere(red), Matrix4d.CreateTranslation(0.0, -0.8, -1.1));
    czech.InsertChild(ColoredSphere(blue), Matrix4d.CreateTranslation(-1.0, 0.0, -0.8));
    flags.InsertChild(czech, Matrix4d.Scale(1.6, 1.0, 1.0) * Matrix4d.CreateRotationY(Math.PI / 8) * Matrix4d.CreateTranslation(4.0, -1.5, 0.0));

    // Croatia (union of stripes, intersection for the coat of arms).
    var croatianFlag = new CSGInnerNode(SetOperation.Union);
    var croatianSign = new CSGInnerNode(SetOperation.Intersection);
    Cube board = ColoredCube(red);
    board.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(10.0, 10.0, white));
    croatianSign.InsertChild(board, centre * Matrix4d.Scale(2.0, 2.0, 0.4));
    var sign = new CSGInnerNode(SetOperation.Union);
    sign.InsertChild(ColoredSphere(white), Matrix4d.Identity);
    sign.InsertChild(ColoredCube(white), Matrix4d.Scale(1.8) * Matrix4d.CreateTranslation(-0.9, 0.1, -0.9));
    croatianSign.InsertChild(sign, Matrix4d.Scale(0.5, 0.33, 0.5) * Matrix4d.CreateTranslation(0.44, -0.5, 0.0));
    Matrix4d stripe = centre * Matrix4d.Scale(4.0, 0.6, 0.6) * Matrix4d.RotateX(Math.PI / 4);
    croatianFlag.InsertChild(ColoredCube(red), stripe * Matrix4d.CreateTranslation(0.5, 1.0, 1.0));
    croatianFlag.InsertChild(ColoredCube(white), stripe * Matrix4d.CreateTranslation(0.5, 0.3, 1.0));
    croatianFlag.InsertChild(ColoredCube(blue), stripe * Matrix4d.CreateTranslation(0.5, -0.4, 1.0));
    croatianFlag.InsertChild(croatianSign, Matrix4d.Scale(0.8) * Matrix4d.CreateTranslation(0.4, 0.5, 0.0));
    flags.InsertChild(croatianFlag, Matrix4d.Scale(0.8) * Matrix4d.CreateRotationY(Math.PI / 8) * Matrix4d.CreateTranslation(-0.4, 1.5, 1.0));

    // Brazil (union).
    var brazilianFlag = new CSGInnerNode(SetOperation.Union);
    brazilianFlag.InsertChild(ColoredCube(new[] { 0.0, 0.8, 0.0 }), centre * Matrix4d.Scale(4.0, 2.0, 0.2));
    brazilianFlag.InsertChild(ColoredCube(new[] { 1.0, 1.0, 0.0 }), centre * Matrix4d.CreateRotationZ(Math.PI / 4) * Matrix4d.Scale(2.0, 1.0, 0.4));
    brazilianFlag.InsertChild(ColoredSphere(blue), Matrix4d.Scale(0.5) * Matrix4d.CreateTranslation(0.0, 0.0, 0.0));
    flags.InsertChild(brazilianFlag, Matrix4d.Scale(0.9) * Matrix4d.RotateY(-Math.PI / 8) * Matrix4d.CreateTranslation(0.0, -1.8, 1.0));

    // Finland (difference: a cross cut into a flattened sphere).
    var finlandFlag = new CSGInnerNode(SetOperation.Difference);
    finlandFlag.InsertChild(ColoredSphere(white), Matrix4d.Scale(2.0, 1.0, 0.5) * Matrix4d.CreateTranslation(0.0, 0.0, 0.3));
    finlandFlag.InsertChild(ColoredCube(blue), centre * Matrix4d.Scale(4.2, 0.5, 0.5));
    finlandFlag.InsertChild(ColoredCube(blue), centre * Matrix4d.Scale(0.5, 4.2, 0.5) * Matrix4d.CreateTranslation(-0.5, 0.0, 0.0));
    flags.InsertChild(finlandFlag, Matrix4d.Scale(0.7) * Matrix4d.CreateTranslation(3.5, 1.5, 0.0));

    // Cuba (union of stepped stripes and an intersected wedge).
    var cubanFlag = new CSGInnerNode(SetOperation.Union);
    for (int i = 0; i < 5; i++)
      cubanFlag.InsertChild(ColoredCube(i % 2 == 0 ? blue : white),
        centre * Matrix4d.Scale(4.0, 0.4, 0.4) * Matrix4d.CreateTranslation(new Vector3d(0.0, 0.0 - i * 0.4, 0.8 - i * 0.2)));
    var wedge = new CSGInnerNode(SetOperation.Intersection);
    wedge.InsertChild(ColoredCube(red), centre * Matrix4d.Scale(2.0, 2.0, 2.0) * Matrix4d.CreateRotationZ(Math.PI / 4));
    wedge.InsertChild(ColoredCube(red), Matrix4d.Scale(4.0) * Matrix4d.CreateTranslation(0.0, -2.0, -2.0));
    cubanFlag.InsertChild(wedge, Matrix4d.Scale(0.7) * Matrix4d.CreateTranslation(-2.0001, -0.8, 0.4999));
    flags.InsertChild(cubanFlag, Matrix4d.Scale(0.7) * Matrix4d.RotateY(Math.PI / 8) * Matrix4d.CreateTranslation(-4.0, -1.0, 0.0));
  }
}
