using OpenTK.Mathematics;

namespace Rendering;

public partial class Scenes
{
  /// <summary>
  /// A glass sphere and an opaque one on a checkered plane. Parameter: <c>n</c> = index of
  /// refraction of the glass (default 1.6).
  /// </summary>
  public static void TwoSpheres(IRayScene sc, string param)
  {
    CSGInnerNode root = Root(sc, new PhongMaterial(new[] { 1.0, 0.8, 0.1 }, 0.1, 0.6, 0.4, 128));
    sc.BackgroundColor = new[] { 0.0, 0.05, 0.07 };
    sc.Camera = new StaticCamera(new Vector3d(0.7, 0.5, -5.0), new Vector3d(0.0, -0.18, 1.0), 50.0);
    Lights(sc, 0.8, new Vector3d(-5.0, 4.0, -3.0), 1.2);

    var p = ParseParams(param);
    double n = 1.6;
    TryParam(p, "n", ref n);

    var glass = new PhongMaterial(new[] { 0.0, 0.2, 0.1 }, 0.05, 0.05, 0.1, 128) { n = n, Kt = 0.9 };
    var s = new Sphere();
    s.SetAttribute(PropertyName.MATERIAL, glass);
    root.InsertChild(s, Matrix4d.Identity);

    root.InsertChild(new Sphere(), Matrix4d.Scale(1.2) * Matrix4d.CreateTranslation(1.5, 0.2, 2.4));
    Floor(root, new[] { 0.3, 0.0, 0.0 }, 0.6, new[] { 1.0, 1.0, 1.0 });
  }
}
