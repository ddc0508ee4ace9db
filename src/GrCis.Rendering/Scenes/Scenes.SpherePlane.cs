using OpenTK.Mathematics;

namespace Rendering;

public partial class Scenes
{
  /// <summary>An orange sphere on an infinite checkered plane (GrCis's default scene).</summary>
  public static void SpherePlane(IRayScene sc)
  {
    CSGInnerNode root = Root(sc, new PhongMaterial(new[] { 1.0, 0.6, 0.1 }, 0.1, 0.6, 0.4, 16));
    sc.BackgroundColor = new[] { 0.0, 0.05, 0.07 };
    sc.Camera = new StaticCamera(new Vector3d(0.7, 0.5, -5.0), new Vector3d(0.0, -0.18, 1.0), 50.0);
    Lights(sc, 0.8, new Vector3d(-5.0, 3.0, -3.0), 1.0);

    root.InsertChild(new Sphere(), Matrix4d.Identity);
    Floor(root, new[] { 0.5, 0.0, 0.0 }, 1.0, new[] { 1.0, 1.0, 1.0 });
  }
}
