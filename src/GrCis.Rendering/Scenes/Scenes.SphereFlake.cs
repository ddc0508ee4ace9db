using OpenTK.Mathematics;

namespace Rendering;

public partial class Scenes
{
  /// <summary>
  /// A sphere flake on a checkered plane. Parameters: <c>depth</c> (levels, default 5),
  /// <c>coef</c> (child scale, 0.4), <c>mat</c> = mirror | glass (else diffuse), <c>n</c> (glass IOR, 1.6).
  /// </summary>
  public static void SphereFlake(IRayScene sc, string param)
  {
    CSGInnerNode root = Root(sc, new PhongMaterial(new[] { 1.0, 0.8, 0.1 }, 0.1, 0.6, 0.4, 128));
    sc.BackgroundColor = new[] { 0.0, 0.05, 0.07 };
    sc.Camera = new StaticCamera(new Vector3d(1.6, 2.2, -7.0), new Vector3d(-0.12, -0.3, 1.0), 50.0);
    Lights(sc, 0.8, new Vector3d(-5.0, 4.0, -3.0), 1.2);

    var p = ParseParams(param);
    int depth = 5;
    TryParam(p, "depth", ref depth);
    double n = 1.6;
    TryParam(p, "n", ref n);
    double coef = 0.4;
    TryParam(p, "coef", ref coef);

    ISceneNode sf = flake(depth, coef);
    sf.SetAttribute(PropertyName.MATERIAL, FlakeMaterial(p, n, new PhongMaterial(new[] { 1.0, 0.6, 0.1 }, 0.1, 0.85, 0.05, 16)));
    root.InsertChild(sf, Matrix4d.Identity);

    Floor(root, new[] { 0.3, 0.0, 0.0 }, 0.6, new[] { 1.0, 1.0, 1.0 });
  }

  /// <summary>The <c>mat</c> parameter of Sphere flake and Cubes: mirror, glass, or <paramref name="diffuse"/>.</summary>
  static PhongMaterial FlakeMaterial(System.Collections.Generic.Dictionary<string, string> p, double n, PhongMaterial diffuse) =>
    p.TryGetValue("mat", out string? mat) ? mat switch
    {
      "mirror" => new PhongMaterial(new[] { 1.0, 1.0, 0.8 }, 0.0, 0.1, 0.9, 128),
      "glass" => new PhongMaterial(new[] { 0.0, 0.2, 0.1 }, 0.05, 0.05, 0.1, 128) { n = n, Kt = 0.9 },
      _ => diffuse,
    } : diffuse;
}
