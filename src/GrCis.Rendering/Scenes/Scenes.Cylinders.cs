using OpenTK.Mathematics;

namespace Rendering;

public partial class Scenes
{
  /// <summary>Infinite, half-infinite and capped cylinders over a checkered plane.</summary>
  public static void Cylinders(IRayScene sc)
  {
    CSGInnerNode root = Root(sc, new PhongMaterial(new[] { 0.6, 0.0, 0.0 }, 0.15, 0.8, 0.15, 16));
    sc.BackgroundColor = new[] { 0.0, 0.05, 0.07 };
    sc.Camera = new StaticCamera(new Vector3d(0.7, 3.0, -10.0), new Vector3d(0.0, -0.2, 1.0), 50.0);
    Lights(sc, 1.0, new Vector3d(-5.0, 3.0, -3.0), 1.6);

    Floor(root, new[] { 0.0, 0.2, 0.0 }, 0.5, new[] { 1.0, 1.0, 1.0 });

    // Infinite horizontal tube in the root material.
    root.InsertChild(new Cylinder(), Matrix4d.RotateX(MathHelper.PiOver2) * Matrix4d.CreateTranslation(-2.1, 0.0, 1.0));

    // Infinite striped tube leaning away.
    var c = new Cylinder();
    c.SetAttribute(PropertyName.COLOR, new[] { 0.2, 0.0, 0.7 });
    c.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(12.0, 1.0, new[] { 0.0, 0.0, 0.3 }));
    root.InsertChild(c, Matrix4d.RotateY(-0.4) * Matrix4d.CreateTranslation(1.0, 0.0, 1.0));

    root.InsertChild(ColoredCylinder(new[] { 0.1, 0.7, 0.0 }, 0.0, 100.0), Matrix4d.RotateY(0.2) * Matrix4d.CreateTranslation(5.0, 0.3, 4.0));
    root.InsertChild(ColoredCylinder(new[] { 0.8, 0.6, 0.0 }), Matrix4d.Scale(2.0) * Matrix4d.RotateX(1.2) * Matrix4d.CreateTranslation(2.0, 1.8, 16.0));
  }
}
