using Scene3D;
using System;
using OpenTK.Mathematics;

namespace Rendering;

public partial class Scenes
{
  /// <summary>
  /// The POV-Ray peer flake (shared/bench/povray/sphereflake.pov): Haines's layout, 9 children of
  /// radius 1/3 touching each parent, <paramref name="depth"/> levels (4: 7,381 spheres), as nested
  /// unions with one transform per level, on the Sphere flake's floor, camera and lights.
  /// Not in the registry of classic scenes (a benchmark scene).
  /// </summary>
  public static void SphereFlake9(IRayScene sc, int depth = 4)
  {
    CSGInnerNode root = Root(sc, new PhongMaterial(new[] { 1.0, 0.8, 0.1 }, 0.1, 0.6, 0.4, 128));
    sc.BackgroundColor = new[] { 0.0, 0.05, 0.07 };
    sc.Camera = new StaticCamera(new Vector3d(1.6, 2.2, -7.0), new Vector3d(-0.12, -0.3, 1.0), 50.0);
    Lights(sc, 0.8, new Vector3d(-5.0, 4.0, -3.0), 1.2);

    ISceneNode sf = Flake9Node(depth, Flake9Transforms());
    sf.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 1.0, 0.6, 0.1 }, 0.1, 0.6, 0.3, 16));
    root.InsertChild(sf, Matrix4d.Identity);
    Floor(root, new[] { 0.3, 0.0, 0.0 }, 0.6, new[] { 1.0, 1.0, 1.0 });
  }

  /// <summary>Spheres in <see cref="SphereFlake9"/> at a depth: 1 + 9 + 81 + …</summary>
  public static int SphereFlake9Count(int depth) => depth < 0 ? 0 : 1 + 9 * SphereFlake9Count(depth - 1);

  static ISceneNode Flake9Node(int depth, Matrix4d[] children)
  {
    var node = new CSGInnerNode(SetOperation.Union);
    node.InsertChild(new Sphere(), Matrix4d.Identity);
    if (depth > 0)
      foreach (Matrix4d m in children)
        node.InsertChild(Flake9Node(depth - 1, children), m);
    return node;
  }

  /// <summary>The nine child frames of the POV-Ray peer flake (also used by the fast-path tests).</summary>
  public static Matrix4d[] Flake9Transforms()
  {
    // Child directions with the parent's axis +y: 6 on the equator, 3 above (the SPD "balls" set).
    var dirs = new Vector3d[9];
    for (int k = 0; k < 6; k++)
    {
      double az = (15 + 60 * k) * Math.PI / 180;
      dirs[k] = new Vector3d(Math.Cos(az), 0, -Math.Sin(az));
    }
    double el = Math.Asin(Math.Sqrt(2.0 / 3.0));
    for (int k = 0; k < 3; k++)
    {
      double az = (45 + 120 * k) * Math.PI / 180;
      dirs[6 + k] = new Vector3d(Math.Cos(el) * Math.Cos(az), Math.Sin(el), -Math.Cos(el) * Math.Sin(az));
    }
    var result = new Matrix4d[9];
    for (int k = 0; k < 9; k++)
    {
      // Child frame: the minimal rotation taking +y onto dirs[k], scaled by 1/3, moved 4/3 out.
      Vector3d d = dirs[k];
      Vector3d axis = Vector3d.Cross(Vector3d.UnitY, d);
      double angle = Math.Acos(Math.Clamp(d.Y, -1, 1));
      Matrix4d r = axis.LengthSquared < 1e-24 ? Matrix4d.Identity : Matrix4d.CreateFromAxisAngle(axis.Normalized(), angle);
      if ((Vector3d.TransformVector(Vector3d.UnitY, r) - d).Length > 1e-9)
        r = Matrix4d.CreateFromAxisAngle(axis.Normalized(), -angle);
      result[k] = Matrix4d.Scale(1.0 / 3.0) * r * Matrix4d.CreateTranslation(d * (4.0 / 3.0));
    }
    return result;
  }

  /// <summary>
  /// A triangle mesh above the Sphere flake's floor under its camera and lights: scaled to box
  /// diagonal 3 about its centre and, with <paramref name="tilt"/>, turned to face the camera.
  /// A benchmark scene (meshes from <see cref="ProceduralMesh"/> or an OBJ file).
  /// </summary>
  public static void MeshScene(IRayScene sc, SceneBrep mesh, bool tilt = true)
  {
    ArgumentNullException.ThrowIfNull(mesh);
    CSGInnerNode root = Root(sc, new PhongMaterial(new[] { 1.0, 0.8, 0.1 }, 0.1, 0.6, 0.4, 128));
    sc.BackgroundColor = new[] { 0.0, 0.05, 0.07 };
    sc.Camera = new StaticCamera(new Vector3d(1.6, 2.2, -7.0), new Vector3d(-0.12, -0.3, 1.0), 50.0);
    Lights(sc, 0.8, new Vector3d(-5.0, 4.0, -3.0), 1.2);

    var solid = new TriangleMesh(mesh);
    solid.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.2, 0.5, 1.0 }, 0.1, 0.7, 0.2, 32));
    float diameter = mesh.GetDiameter(out Vector3 center);
    double scale = diameter > 0f ? 3.0 / diameter : 1.0;
    Matrix4d m = Matrix4d.CreateTranslation(-(Vector3d)center) * Matrix4d.Scale(scale);
    if (tilt)
      m *= Matrix4d.RotateX(-0.9);
    root.InsertChild(solid, m);
    Floor(root, new[] { 0.3, 0.0, 0.0 }, 0.6, new[] { 1.0, 1.0, 1.0 });
  }
}
