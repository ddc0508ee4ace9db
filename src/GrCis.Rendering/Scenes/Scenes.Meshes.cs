using System;
using System.Collections.Generic;
using System.IO;
using OpenTK.Mathematics;
using Scene3D;

namespace Rendering;

/// <summary>GrCis's mesh scenes: an OBJ model lit and framed automatically (the demo's "Str" scenes).</summary>
public partial class Scenes
{
  /// <summary>Names of the mesh scenes, in GrCis's order (see <see cref="InitFunctionsStr"/>).</summary>
  public static string[] NamesStr = { "Teapot", "Pitcher", "Buddha", "Toy-plane" };

  /// <summary>The mesh scenes' initializers; each takes the OBJ file name(s) to use (empty = its default file).</summary>
  public static InitSceneStrDelegate[] InitFunctionsStr = { TeapotObj, PitcherObj, BuddhaObj, PlaneObj };

  /// <summary>The classic scenes by GrCis name: an <see cref="InitSceneDelegate"/> or an <see cref="InitSceneParamDelegate"/>.</summary>
  public static Dictionary<string, object> staticRepository = new()
  {
    ["Five balls"] = new InitSceneDelegate(FiveBalls),
    ["Hedgehog in the cage"] = new InitSceneDelegate(HedgehogInTheCage),
    ["Flags"] = new InitSceneDelegate(Flags),
    ["Sphere on the plane"] = new InitSceneDelegate(SpherePlane),
    ["Two spheres"] = new InitSceneParamDelegate(TwoSpheres),
    ["Sphere flake"] = new InitSceneParamDelegate(SphereFlake),
    ["Cubes"] = new InitSceneParamDelegate(Cubes),
    ["Cylinders"] = new InitSceneDelegate(Cylinders),
    ["Circus"] = new InitSceneDelegate(Circus),
    ["Toroids"] = new InitSceneDelegate(Toroids),
    ["Bezier"] = new InitSceneDelegate(Bezier),
  };

  /// <summary>GrCis's name of <see cref="staticRepository"/> until March 2018 (course years 2015/16 and 2016/17).</summary>
  public static Dictionary<string, object> Repository
  {
    get => staticRepository;
    set => staticRepository = value;
  }

  /// <summary>The teapot scene: <c>teapot.obj</c> (or the first of <paramref name="names"/>) in orange, framed automatically.</summary>
  /// <param name="sc">The scene to fill.</param>
  /// <param name="names">OBJ file names; empty (or an empty first name) for the default file.</param>
  /// <returns>The number of triangles read (0 when no file was found and a sphere stands in).</returns>
  public static long TeapotObj(IRayScene sc, string[] names) =>
    SceneObj(sc, new Vector3d(0.1, -0.3, 0.9), 50.0, 0.9, "teapot.obj", names, new[] { 1.0, 0.6, 0.0 });

  /// <summary>The pitcher scene: <c>pitcher.obj</c> (or the first of <paramref name="names"/>) in green, framed automatically.</summary>
  /// <param name="sc">The scene to fill.</param>
  /// <param name="names">OBJ file names; empty (or an empty first name) for the default file.</param>
  /// <returns>The number of triangles read (0 when no file was found and a sphere stands in).</returns>
  public static long PitcherObj(IRayScene sc, string[] names) =>
    SceneObj(sc, new Vector3d(0.6, -0.3, 0.5), 60.0, 1.1, "pitcher.obj", names, new[] { 0.3, 0.6, 0.0 });

  /// <summary>The Buddha scene: <c>buddha.obj</c> (or the first of <paramref name="names"/>) in orange, framed automatically.</summary>
  /// <param name="sc">The scene to fill.</param>
  /// <param name="names">OBJ file names; empty (or an empty first name) for the default file.</param>
  /// <returns>The number of triangles read (0 when no file was found and a sphere stands in).</returns>
  public static long BuddhaObj(IRayScene sc, string[] names) =>
    SceneObj(sc, new Vector3d(0.4, -0.3, -0.9), 70.0, 1.1, "buddha.obj", names, new[] { 1.0, 0.4, 0.0 });

  /// <summary>The toy-plane scene: <c>toyplane.obj</c> (or the first of <paramref name="names"/>) in green, framed automatically.</summary>
  /// <param name="sc">The scene to fill.</param>
  /// <param name="names">OBJ file names; empty (or an empty first name) for the default file.</param>
  /// <returns>The number of triangles read (0 when no file was found and a sphere stands in).</returns>
  public static long PlaneObj(IRayScene sc, string[] names) =>
    SceneObj(sc, new Vector3d(-0.7, -0.25, 0.7), 70.0, 0.9, "toyplane.obj", names, new[] { 0.2, 0.8, 0.0 });

  /// <summary>
  /// Finds each file: a name with a folder in it is taken as it is (GrCis's backslashes read as
  /// separators); a bare name is searched for below the current folder, then below up to three
  /// levels of parents (at most eight folders deep, unreadable folders skipped). Null where not found.
  /// </summary>
  public static string?[]? SmartFindFiles(string[]? names)
  {
    if (names == null || names.Length == 0)
      return null;
    var result = new string?[names.Length];
    var options = new EnumerationOptions { RecurseSubdirectories = true, IgnoreInaccessible = true, MaxRecursionDepth = 8 };
    for (int i = 0; i < names.Length; i++)
    {
      string name = names[i];
      if (string.IsNullOrEmpty(name))
      {
        result[i] = "";
        continue;
      }
      if (name.Contains('\\') || name.Contains('/'))
      {
        result[i] = Utilities.DataFiles.Resolve(name);
        continue;
      }
      foreach (string root in new[] { ".", "..", Path.Combine("..", ".."), Path.Combine("..", "..", "..") })
      {
        try
        {
          using IEnumerator<string> found = Directory.EnumerateFiles(root, name, options).GetEnumerator();
          if (found.MoveNext())
          {
            result[i] = found.Current;
            break;
          }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
          // A folder that cannot be searched: try the next one.
        }
      }
    }
    return result;
  }

  /// <summary>
  /// The mesh scene: the OBJ file (or, when missing, its .gz, else a unit sphere) with a Phong material
  /// of <paramref name="surfaceColor"/>, the camera looking along <paramref name="dir"/> from far enough
  /// to see the whole mesh (<paramref name="correction"/> &lt; 1 comes nearer), an ambient and a point light.
  /// Returns the number of triangles read.
  /// </summary>
  protected static long SceneObj(IRayScene sc, Vector3d dir, double FoVy, double correction, string name, string[] names, double[] surfaceColor)
  {
    ArgumentNullException.ThrowIfNull(sc);
    dir.Normalize();
    Vector3 center = Vector3.Zero;
    float diameter = 2.0f;
    int faces = 0;
    var root = new CSGInnerNode(SetOperation.Union);

    if (names == null || names.Length == 0 || string.IsNullOrEmpty(names[0]))
      names = new[] { name };
    string?[] paths = SmartFindFiles(names)!;
    if (string.IsNullOrEmpty(paths[0]) || !File.Exists(paths[0]))
      paths = SmartFindFiles(Array.ConvertAll(names, n => n.Length > 0 ? n + ".gz" : n))!;

    if (string.IsNullOrEmpty(paths[0]) || !File.Exists(paths[0]))
      root.InsertChild(new Sphere(), Matrix4d.Identity);
    else
    {
      var brep = new SceneBrep();
      faces = new WavefrontObj { MirrorConversion = false }.ReadBrep(paths[0]!, brep);
      brep.BuildCornerTable();
      diameter = brep.GetDiameter(out center);
      root.InsertChild(new TriangleMesh(brep), Matrix4d.Identity);
    }

    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(surfaceColor, 0.2, 0.5, 0.4, 32));
    root.SetAttribute(PropertyName.COLOR, surfaceColor);
    sc.Intersectable = root;
    sc.BackgroundColor = new[] { 0.0, 0.05, 0.07 };

    double distance = 0.5 * diameter * correction / Math.Tan(MathHelper.DegreesToRadians((float)(0.5 * FoVy)));
    sc.Camera = new StaticCamera((Vector3d)center - distance * dir, dir, FoVy);

    sc.Sources = new LinkedList<ILightSource>();
    sc.Sources.Add(new AmbientLightSource(0.8));
    Vector3d lightDir = Vector3d.TransformVector(dir, Matrix4d.CreateRotationY(-2.0));
    lightDir = Vector3d.TransformVector(lightDir, Matrix4d.CreateRotationZ(-0.8));
    sc.Sources.Add(new PointLightSource((Vector3d)center + diameter * lightDir, 1.0));
    return faces;
  }
}
