using OpenTK.Mathematics;

namespace Rendering;

public partial class Scenes
{
  /// <summary>
  /// Two rows of rotated unit cubes on a checkered plane. Parameters: <c>mat</c> = mirror | glass
  /// (else diffuse), <c>n</c> (glass IOR, default 1.6).
  /// </summary>
  public static void Cubes(IRayScene sc, string param)
  {
    CSGInnerNode root = Root(sc, new PhongMaterial(new[] { 1.0, 0.6, 0.1 }, 0.1, 0.8, 0.2, 16));
    sc.BackgroundColor = new[] { 0.0, 0.05, 0.07 };
    sc.Camera = new StaticCamera(new Vector3d(0.7, 3.0, -10.0), new Vector3d(0.0, -0.3, 1.0), 50.0);
    Lights(sc, 0.8, new Vector3d(-5.0, 3.0, -3.0), 1.0);

    var p = ParseParams(param);
    double n = 1.6;
    TryParam(p, "n", ref n);
    PhongMaterial pm = FlakeMaterial(p, n, new PhongMaterial(new[] { 1.0, 0.6, 0.1 }, 0.1, 0.8, 0.2, 16));

    Floor(root, new[] { 0.6, 0.0, 0.0 }, 0.5, new[] { 1.0, 1.0, 1.0 });

    // Front row turns about y, back row about x.
    double[] frontAngles = { 0.6, 1.2, 1.8, 2.4, 3.0 };
    for (int i = 0; i < frontAngles.Length; i++)
      AddCube(root, pm, Matrix4d.RotateY(frontAngles[i]) * Matrix4d.CreateTranslation(-3.5 + 2.0 * i, -0.8, 0.0));
    double[] backAngles = { 3.5, 3.0, 2.5, 2.0, 1.5, 1.0, 0.5 };
    for (int i = 0; i < backAngles.Length; i++)
      AddCube(root, pm, Matrix4d.RotateX(backAngles[i]) * Matrix4d.CreateTranslation(-4.0 + 1.5 * i, 1.0, 2.0));
  }

  static void AddCube(CSGInnerNode root, PhongMaterial material, Matrix4d toParent)
  {
    var c = new Cube();
    c.SetAttribute(PropertyName.MATERIAL, material);
    root.InsertChild(c, toParent);
  }
}
