using OpenTK.Mathematics;

namespace Rendering;

public partial class Scenes
{
  /// <summary>Tori (by J. Navratil, 2012): a ring torus, a bitten spindle "donut" and a row of thin rings.</summary>
  public static void Toroids(IRayScene sc)
  {
    CSGInnerNode root = Root(sc, new PhongMaterial(new[] { 0.5, 0.5, 0.5 }, 0.2, 0.7, 0.2, 16));
    sc.BackgroundColor = new[] { 0.0, 0.15, 0.2 };
    sc.Camera = new StaticCamera(new Vector3d(0.0, 0.0, -10.0), new Vector3d(0.0, -0.04, 1.0), 60.0);
    Lights(sc, 1.8, new Vector3d(-5.0, 3.0, -3.0), 2.0);

    var t = new Torus(2.0, 1.0);
    t.SetAttribute(PropertyName.COLOR, new[] { 0.0, 0.0, 0.7 });
    t.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(50.0, 20.0, new[] { 0.9, 0.9, 0.0 }));
    root.InsertChild(t, Matrix4d.Scale(0.8) * Matrix4d.CreateRotationX(0.9) * Matrix4d.CreateTranslation(2.7, 0.6, 0.0));

    // Spindle torus with a big bite taken out by a sphere.
    var donut = new CSGInnerNode(SetOperation.Difference);
    t = new Torus(1.0, 1.5);
    t.SetAttribute(PropertyName.COLOR, new[] { 1.0, 0.0, 0.0 });
    t.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(40.0, 40.0, new[] { 0.8, 1.0, 1.0 }));
    donut.InsertChild(t, Matrix4d.Identity);
    Sphere s = ColoredSphere(new[] { 0.5, 0.5, 0.5 });
    s.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(100.0, 100.0, new[] { 1.0, 0.5, 0.0 }));
    donut.InsertChild(s, Matrix4d.Scale(3.0) * Matrix4d.CreateTranslation(0.0, -3.0, 0.0));
    root.InsertChild(donut, Matrix4d.CreateRotationX(0.8) * Matrix4d.CreateTranslation(-2.5, 0.0, 0.0));

    // Rings of growing thickness, each turned a bit more.
    const int number = 14;
    for (int i = 0; i < number; i++)
    {
      t = new Torus(0.2, 0.01 + 0.185 * i / number);
      t.SetAttribute(PropertyName.COLOR, new[] { 1.0, 1.0, 1.0 });
      root.InsertChild(t, Matrix4d.CreateRotationX(0.5 * i) * Matrix4d.CreateTranslation(10.0 * (1.0 * i / number) - 4.7, -2.5, 0.0));
    }
  }
}
