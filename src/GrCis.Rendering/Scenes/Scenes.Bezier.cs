using OpenTK.Mathematics;

namespace Rendering;

public partial class Scenes
{
  /// <summary>A checkered bicubic Bezier surface (1×2 patches) with two reflecting cylinders over a checkered plane.</summary>
  public static void Bezier(IRayScene sc)
  {
    CSGInnerNode root = Root(sc, new PhongMaterial(new[] { 1.0, 0.8, 0.1 }, 0.1, 0.5, 0.5, 64));
    sc.BackgroundColor = new[] { 0.0, 0.05, 0.07 };
    sc.Camera = new StaticCamera(new Vector3d(0.7, 0.5, -5.0), new Vector3d(0.0, -0.18, 1.0), 50.0);
    Lights(sc, 0.8, new Vector3d(-5.0, 3.0, -3.0), 1.0);

    // Control net: 4 rows of 7 points (x, y, z); the bumps rise in y.
    var b = new BezierSurface(1, 2, new[]
    {
      0.0, 0.0, 3.0,  1.0, 0.0, 3.0,  2.0, 0.0, 3.0,  3.0, 0.0, 3.0,  4.0, 0.0, 3.0,  5.0, 0.0, 3.0,  6.0, 0.0, 3.0,
      0.0, 0.0, 2.0,  1.0, 0.0, 2.0,  2.0, 3.0, 2.0,  3.0, 3.0, 2.0,  4.0, 3.0, 2.0,  5.0, 0.0, 2.0,  6.0, 0.0, 2.0,
      0.0, 0.0, 1.0,  1.0, 0.0, 1.0,  2.0, 0.0, 1.0,  3.0, 1.5, 1.0,  4.0, 3.0, 1.0,  5.0, 0.0, 1.0,  6.0, 0.0, 1.0,
      0.0, 0.0, 0.0,  1.0, 0.0, 0.0,  2.0, 0.0, 0.0,  3.0, 0.0, 0.0,  4.0, 0.0, 0.0,  5.0, 0.0, 0.0,  6.0, 0.0, 0.0,
    });
    b.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(10.5, 12.0, new[] { 0.0, 0.0, 0.1 }));
    root.InsertChild(b, Matrix4d.RotateY(-0.4) * Matrix4d.CreateTranslation(-1.1, -0.9, 0.0));

    // Two thin infinite cylinders to show reflections.
    var c = new Cylinder();
    c.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.0, 0.6, 0.0 }, 0.2, 0.6, 0.3, 8));
    root.InsertChild(c, Matrix4d.Scale(0.15) * Matrix4d.RotateX(MathHelper.PiOver2) * Matrix4d.CreateTranslation(-0.4, 0.0, 0.0));
    c = new Cylinder();
    c.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.8, 0.2, 0.0 }, 0.2, 0.6, 0.3, 8));
    root.InsertChild(c, Matrix4d.Scale(0.2) * Matrix4d.RotateX(MathHelper.PiOver2) * Matrix4d.CreateTranslation(-1.9, 0.0, 3.0));

    Floor(root, new[] { 0.3, 0.0, 0.0 }, 0.6, new[] { 1.0, 1.0, 1.0 });
  }
}
