using System;
using System.Collections.Generic;
using System.Diagnostics.CodeAnalysis;
using System.Globalization;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// The classic GrCis scenes (mostly by students of the course) and the ready-made scene parts
/// that scene scripts call. Each scene fills a <see cref="DefaultRayScene"/>; the registry finds
/// one by its GrCis name ("Five balls"), its method name ("FiveBalls") or either in any case.
/// </summary>
public partial class Scenes
{
  /// <summary>GrCis's default scene.</summary>
  public const string DefaultSceneName = "Sphere on the plane";

  // Display name, compact (method / reference-image) name, initializer; in GrCis's order.
  static readonly (string Name, string Compact, InitSceneParamDelegate Init)[] registry =
  {
    ("Five balls", nameof(FiveBalls), (sc, _) => FiveBalls(sc)),
    ("Hedgehog in the cage", nameof(HedgehogInTheCage), (sc, _) => HedgehogInTheCage(sc)),
    ("Flags", nameof(Flags), (sc, _) => Flags(sc)),
    ("Sphere on the plane", nameof(SpherePlane), (sc, _) => SpherePlane(sc)),
    ("Two spheres", nameof(TwoSpheres), TwoSpheres),
    ("Sphere flake", nameof(SphereFlake), SphereFlake),
    ("Cubes", nameof(Cubes), Cubes),
    ("Cylinders", nameof(Cylinders), (sc, _) => Cylinders(sc)),
    ("Circus", nameof(Circus), (sc, _) => Circus(sc)),
    ("Toroids", nameof(Toroids), (sc, _) => Toroids(sc)),
    ("Bezier", nameof(Bezier), (sc, _) => Bezier(sc)),
    ("Test scene", nameof(TestScene), (sc, _) => TestScene(sc)),
  };

  static readonly string[] names = Array.ConvertAll(registry, r => r.Name);

  /// <summary>Names of the built-in scenes in GrCis's order.</summary>
  public static IReadOnlyList<string> Names => names;

  /// <summary>
  /// Finds a scene by name, ignoring case, spaces and punctuation: "Sphere on the plane",
  /// "SpherePlane" and "sphereplane" all work.
  /// </summary>
  public static bool TryGet(string? name, [NotNullWhen(true)] out InitSceneParamDelegate? init)
  {
    int i = IndexOf(name);
    init = i >= 0 ? registry[i].Init : null;
    return init != null;
  }

  /// <summary>The registered (display) name for <paramref name="name"/>, or null when unknown.</summary>
  public static string? CanonicalName(string? name)
  {
    int i = IndexOf(name);
    return i >= 0 ? registry[i].Name : null;
  }

  /// <summary>A new scene filled by the named initializer.</summary>
  /// <exception cref="ArgumentException">No scene of that name; the message lists the known ones.</exception>
  public static IRayScene Create(string name, string? param = null)
  {
    if (!TryGet(name, out InitSceneParamDelegate? init))
      throw new ArgumentException($"Unknown scene '{name}'. Known scenes: {string.Join(", ", names)}.", nameof(name));
    var sc = new DefaultRayScene();
    init(sc, param ?? string.Empty);
    return sc;
  }

  /// <summary>Something very simple: fills (or creates) a scene with "Sphere on the plane".</summary>
  public static IRayScene DefaultScene(IRayScene? sc = null)
  {
    sc ??= new DefaultRayScene();
    SpherePlane(sc);
    return sc;
  }

  static int IndexOf(string? name)
  {
    if (string.IsNullOrWhiteSpace(name))
      return -1;
    name = name.Trim();
    for (int i = 0; i < registry.Length; i++)
      if (string.Equals(registry[i].Name, name, StringComparison.OrdinalIgnoreCase) ||
          string.Equals(registry[i].Compact, name, StringComparison.OrdinalIgnoreCase))
        return i;
    string key = Compact(name);
    for (int i = 0; i < registry.Length; i++)
      if (key == Compact(registry[i].Name) || key == Compact(registry[i].Compact))
        return i;
    return -1;
  }

  static string Compact(string s)
  {
    var chars = new char[s.Length];
    int n = 0;
    foreach (char c in s)
      if (char.IsLetterOrDigit(c))
        chars[n++] = char.ToLowerInvariant(c);
    return new string(chars, 0, n);
  }

  // --- Parameter parsing (same rules as Util.ParseKeyValueList / Util.TryParse) ---

  /// <summary>"a=1, b=x, c" → {a:"1", b:"x", c:""}; keys and values trimmed, later keys win.</summary>
  static Dictionary<string, string> ParseParams(string? param)
  {
    var result = new Dictionary<string, string>();
    if (string.IsNullOrEmpty(param))
      return result;
    foreach (string segment in param.Split(','))
    {
      int eq = segment.IndexOf('=');
      string key = (eq < 0 ? segment : segment[..eq]).Trim();
      if (key.Length == 0)
        continue;
      result[key] = eq < 0 ? string.Empty : segment[(eq + 1)..].Trim();
    }
    return result;
  }

  static void TryParam(Dictionary<string, string> p, string key, ref double value)
  {
    if (p.TryGetValue(key, out string? s) &&
        double.TryParse(s, NumberStyles.Float, CultureInfo.InvariantCulture, out double v))
      value = v;
  }

  static void TryParam(Dictionary<string, string> p, string key, ref int value)
  {
    if (p.TryGetValue(key, out string? s) &&
        int.TryParse(s, NumberStyles.Integer, CultureInfo.InvariantCulture, out int v))
      value = v;
  }

  // --- Shared pieces of the scenes ---

  /// <summary>Union root with the Phong model and the given default material; becomes the scene's geometry.</summary>
  static CSGInnerNode Root(IRayScene sc, PhongMaterial material)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, material);
    sc.Intersectable = root;
    return root;
  }

  /// <summary>Ambient light followed by one point light.</summary>
  static void Lights(IRayScene sc, double ambient, Vector3d position, double intensity) =>
    sc.Sources = new LinkedList<ILightSource>(new ILightSource[]
    {
      new AmbientLightSource(ambient),
      new PointLightSource(position, intensity),
    });

  /// <summary>The infinite checkered floor at y = -1 (local z = 0 plane turned to face +y).</summary>
  static void Floor(CSGInnerNode root, double[] color, double cell, double[] color2)
  {
    var pl = new Plane();
    pl.SetAttribute(PropertyName.COLOR, color);
    pl.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(cell, cell, color2));
    root.InsertChild(pl, Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.0, 0.0));
  }

  static Sphere ColoredSphere(double[] color)
  {
    var s = new Sphere();
    s.SetAttribute(PropertyName.COLOR, color);
    return s;
  }

  static Cylinder ColoredCylinder(double[] color, double zMin = -0.5, double zMax = 0.5)
  {
    var c = new Cylinder(zMin, zMax);
    c.SetAttribute(PropertyName.COLOR, color);
    return c;
  }

  static Cube ColoredCube(double[] color)
  {
    var c = new Cube();
    c.SetAttribute(PropertyName.COLOR, color);
    return c;
  }

  // --- Ready-made parts used by scripts (Circus and others) ---

  /// <summary>A clown head with a hat, eyes, nose and mouth (by A. Hanka), about 2.3 units in radius.</summary>
  public static CSGInnerNode head()
  {
    double[] skin = { 1.0, 0.8, 0.65 };
    double[] white = { 1.0, 1.0, 1.0 };
    double[] black = { 0.0, 0.0, 0.0 };
    double[] blue = { 0.0, 0.0, 1.0 };
    double[] red = { 1.0, 0.0, 0.0 };

    var r = new CSGInnerNode(SetOperation.Union);

    // Head with eye sockets carved out.
    var hlava = new CSGInnerNode(SetOperation.Difference);
    r.InsertChild(hlava, Matrix4d.Identity);
    hlava.InsertChild(ColoredSphere(skin), Matrix4d.Scale(2.3));

    // Hat: crown and brim.
    var klobouk = new CSGInnerNode(SetOperation.Union);
    klobouk.InsertChild(ColoredCylinder(black),
      Matrix4d.Scale(2.0, 2.0, 1.4) * Matrix4d.RotateX(Math.PI / 2) * Matrix4d.CreateTranslation(0.0, 0.5, 0.0));
    klobouk.InsertChild(ColoredCylinder(black), Matrix4d.Scale(3.0, 3.0, 0.1) * Matrix4d.RotateX(Math.PI / 2));
    r.InsertChild(klobouk, Matrix4d.CreateTranslation(0.0, 1.25, 0.0));

    hlava.InsertChild(ColoredSphere(skin), Matrix4d.Scale(0.7) * Matrix4d.CreateTranslation(-0.7, 0.3, -1.8));
    hlava.InsertChild(ColoredSphere(skin), Matrix4d.Scale(0.7) * Matrix4d.CreateTranslation(0.7, 0.3, -1.8));

    // Eyes: white ball with a blue iris, right one first.
    foreach (double x in new[] { 0.7, -0.7 })
    {
      var oko = new CSGInnerNode(SetOperation.Union);
      r.InsertChild(oko, Matrix4d.CreateTranslation(x, 0.3, -0.5));
      oko.InsertChild(ColoredSphere(white), Matrix4d.Scale(1.3));
      oko.InsertChild(ColoredSphere(blue), Matrix4d.Scale(0.3) * Matrix4d.CreateTranslation(0.0, 0.0, -1.2));
    }

    // Nose.
    r.InsertChild(ColoredCylinder(skin), Matrix4d.Scale(0.2, 0.2, 0.6) * Matrix4d.CreateTranslation(0.0, 0.0, -2.65));

    // Mouth: xor of two discs (lips), with the dark inside added as a third operand.
    var usta = new CSGInnerNode(SetOperation.Xor);
    usta.InsertChild(ColoredCylinder(red), Matrix4d.CreateTranslation(0.0, -0.3, 0.0));
    usta.InsertChild(ColoredCylinder(red), Matrix4d.CreateTranslation(0.0, 0.3, 0.0));
    r.InsertChild(usta, Matrix4d.Scale(0.7, 0.3, 1.0) * Matrix4d.CreateTranslation(0.0, -0.7, -1.85));

    var vnitrekUst = new CSGInnerNode(SetOperation.Intersection);
    vnitrekUst.InsertChild(ColoredCylinder(black), Matrix4d.CreateTranslation(0.0, -0.3, 0.0));
    vnitrekUst.InsertChild(ColoredCylinder(black), Matrix4d.CreateTranslation(0.0, 0.3, 0.0));
    usta.InsertChild(vnitrekUst, Matrix4d.CreateTranslation(0.0, 0.0, 0.1));

    return r;
  }

  /// <summary>(union of five cylinders) minus (xor of the same five): where at least two overlap.</summary>
  public static CSGInnerNode testWithCylindersXor()
  {
    var node = new CSGInnerNode(SetOperation.Difference);
    node.InsertChild(testWithCylinders(SetOperation.Union), Matrix4d.Identity);
    node.InsertChild(testWithCylinders(SetOperation.Xor), Matrix4d.Identity);
    return node;
  }

  /// <summary>Five tilted unit-height cylinders in a row (green to red), combined by <paramref name="op"/>.</summary>
  public static CSGInnerNode testWithCylinders(SetOperation op)
  {
    const int num = 5;
    var node = new CSGInnerNode(op);
    for (int i = 0; i < num; i++)
    {
      double j = i;
      node.InsertChild(ColoredCylinder(new[] { j / num, 1.0 - j / num, 0.0 }),
        Matrix4d.RotateX(Math.PI / 4) * Matrix4d.CreateTranslation(-1.0 + 0.6 * i, 0.0, 0.0));
    }
    return node;
  }

  /// <summary>Two overlapping unit spheres combined by <paramref name="op"/>.</summary>
  public static CSGInnerNode test2Spheres(SetOperation op)
  {
    var node = new CSGInnerNode(op);
    node.InsertChild(ColoredSphere(new[] { 1.0, 0.3, 1.0 }), Matrix4d.CreateTranslation(-0.3, 0.0, 0.0));
    node.InsertChild(ColoredSphere(new[] { 1.0, 0.3, 0.0 }), Matrix4d.CreateTranslation(0.2, 0.0, -0.2));
    return node;
  }

  /// <summary>A big sphere with five small ones around its front, combined by <paramref name="op"/>.</summary>
  public static CSGInnerNode test6Spheres(SetOperation op)
  {
    double[] orange = { 1.0, 0.3, 0.0 };
    var node = new CSGInnerNode(op);
    node.InsertChild(ColoredSphere(new[] { 1.0, 0.3, 1.0 }), Matrix4d.Scale(2.0));
    node.InsertChild(ColoredSphere(new[] { 0.5, 0.8, 0.2 }), Matrix4d.CreateTranslation(0.0, 0.0, -2.0));
    node.InsertChild(ColoredSphere(orange), Matrix4d.CreateTranslation(0.0, 1.0, -0.5));
    node.InsertChild(ColoredSphere(orange), Matrix4d.CreateTranslation(1.0, 0.0, -0.5));
    node.InsertChild(ColoredSphere(orange), Matrix4d.CreateTranslation(0.0, -1.0, -0.5));
    node.InsertChild(ColoredSphere(orange), Matrix4d.CreateTranslation(-1.0, 0.0, -0.5));
    return node;
  }

  /// <summary>(a ∪ b) − (a xor b) over <see cref="test6Spheres"/>: the parts where spheres overlap.</summary>
  public static CSGInnerNode testXor2()
  {
    var node = new CSGInnerNode(SetOperation.Difference);
    node.InsertChild(test6Spheres(SetOperation.Union), Matrix4d.Identity);
    node.InsertChild(test6Spheres(SetOperation.Xor), Matrix4d.Identity);
    return node;
  }

  /// <summary>
  /// Sphere flake: a unit sphere carrying seven smaller flakes (scaled by <paramref name="coef"/>),
  /// one on top and six around it; <paramref name="depth"/> levels of spheres in total.
  /// </summary>
  public static ISceneNode flake(int depth, double coef)
  {
    var node = new CSGInnerNode(SetOperation.Union);
    node.InsertChild(new Sphere(), Matrix4d.Identity);
    if (--depth <= 0)
      return node;

    // Child placed on the north pole, then tilted down by the tetrahedral angle and turned around y.
    Matrix4d top = Matrix4d.Scale(coef) * Matrix4d.CreateTranslation(0.0, 1.0 + coef, 0.0);
    double a = 2.0 * Math.Atan2(1.0, Math.Sqrt(2.0));
    Matrix4d m1 = top * Matrix4d.RotateX(a);
    Matrix4d m2 = top * Matrix4d.RotateX(a + Math.PI);
    Matrix4d turn1 = Matrix4d.RotateY(2.0 * Math.PI / 3.0);
    Matrix4d turn2 = Matrix4d.RotateY(4.0 * Math.PI / 3.0);

    foreach (Matrix4d m in new[] { top, m1, m2, m1 * turn1, m2 * turn1, m1 * turn2, m2 * turn2 })
      node.InsertChild(flake(depth, coef), m);
    return node;
  }
}
