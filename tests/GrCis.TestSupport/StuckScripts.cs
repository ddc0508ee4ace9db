namespace GrCis.TestSupport;

/// <summary>
/// Scene scripts that never finish, for the tests of stopping user code (command line, demo). Each
/// writes a marker file when it gets stuck, so a test knows the loop is running before it stops it.
/// </summary>
public static class StuckScripts
{
  /// <summary>A camera, no lights, a background: the rest of a scene that renders fast.</summary>
  public const string Camera = """
    scene.Camera = new StaticCamera(new Vector3d(0, 0, -5), new Vector3d(0, 0, 1), 60.0);
    scene.Sources = new LinkedList<ILightSource>();
    scene.BackgroundColor = new double[] { 0.1, 0.2, 0.3 };
    """;

  /// <summary>Writes <paramref name="marker"/>, then loops for ever while building the scene.</summary>
  public static string WhileBuilding(string marker) => Camera + $$"""

    System.IO.File.WriteAllText("{{marker}}", "");
    while (true) { }
    """;

  /// <summary>A texture class of the script that writes <paramref name="marker"/> and loops for ever when rendering reaches it.</summary>
  public static string WhileRendering(string marker) => $$"""
    class Stuck : ITexture
    {
      public long Apply(Intersection inter)
      {
        System.IO.File.WriteAllText("{{marker}}", "");
        while (true) { }
      }
    }
    """ + Camera + """

    var root = new CSGInnerNode(SetOperation.Union);
    var s = new Sphere();
    s.SetAttribute(PropertyName.TEXTURE, new Stuck());
    root.InsertChild(s, Matrix4d.Identity);
    scene.Intersectable = root;
    """;

  /// <summary>
  /// A one-pixel scene (render it at 1×1) whose sphere's texture writes <paramref name="marker"/> and then sleeps for
  /// <paramref name="milliseconds"/>: a class that ignores the stop (no loop to interrupt), so a stopped render ends only
  /// when the sleep does.
  /// </summary>
  public static string Sleeping(string marker, int milliseconds) => $$"""
    class Sleepy : ITexture
    {
      public long Apply(Intersection inter)
      {
        System.IO.File.WriteAllText("{{marker}}", "");
        System.Threading.Thread.Sleep({{milliseconds}});
        return 0L;
      }
    }
    """ + Camera + """

    var root = new CSGInnerNode(SetOperation.Union);
    var s = new Sphere();
    s.SetAttribute(PropertyName.TEXTURE, new Sleepy());
    root.InsertChild(s, Matrix4d.Identity);
    scene.Intersectable = root;
    context[PropertyName.CTX_WIDTH] = 1;
    context[PropertyName.CTX_HEIGHT] = 1;
    """;
}
