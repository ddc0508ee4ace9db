using OpenTK.Mathematics;

namespace Rendering;

public partial class Scenes
{
  /// <summary>Five coloured balls in a row, the rightmost one checkered.</summary>
  public static void FiveBalls(IRayScene sc)
  {
    CSGInnerNode root = Root(sc, new PhongMaterial(new[] { 0.5, 0.5, 0.5 }, 0.1, 0.6, 0.3, 16));
    sc.BackgroundColor = new[] { 0.0, 0.05, 0.05 };
    sc.Camera = new StaticCamera(new Vector3d(0.0, 0.0, -10.0), new Vector3d(0.0, 0.0, 1.0), 60.0);
    Lights(sc, 0.8, new Vector3d(-5.0, 3.0, -3.0), 1.0);

    root.InsertChild(ColoredSphere(new[] { 1.0, 0.6, 0.0 }), Matrix4d.Identity);
    root.InsertChild(ColoredSphere(new[] { 0.2, 0.9, 0.5 }), Matrix4d.CreateTranslation(-2.2, 0.0, 0.0));
    root.InsertChild(ColoredSphere(new[] { 0.1, 0.3, 1.0 }), Matrix4d.CreateTranslation(-4.4, 0.0, 0.0));
    root.InsertChild(ColoredSphere(new[] { 1.0, 0.2, 0.2 }), Matrix4d.CreateTranslation(2.2, 0.0, 0.0));

    Sphere s = ColoredSphere(new[] { 0.1, 0.4, 0.0 });
    s.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(80.0, 40.0, new[] { 1.0, 0.8, 0.2 }));
    root.InsertChild(s, Matrix4d.CreateTranslation(4.4, 0.0, 0.0));
  }
}
