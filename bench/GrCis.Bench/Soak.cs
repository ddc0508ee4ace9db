using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Runtime.Loader;
using GrCis.Interactive;

using GrCis.Hosting;

namespace GrCis.Bench;

/// <summary>
/// <c>soak [--renders N] [--csv FILE]</c>: the demo's (and the studio's) pattern in one process. A
/// student edits a scene script, saves it, and the demo compiles and renders it, N times; then the same
/// script is rendered N times unchanged. After each render: the managed heap after a full collection,
/// the working set, and the script load contexts still alive. The script cache must keep all of them
/// bounded: evicted versions are unloaded.
/// </summary>
public static class Soak
{
  // A scene of realistic size: a class of its own (a texture), a loop, a sphere; each edit changes constants.
  static string Script(int version) => string.Create(CultureInfo.InvariantCulture, $$"""
    // version {{version}}
    class Stripes{{version}} : ITexture
    {
      public long Apply(Intersection inter)
      {
        long band = (long)Math.Floor(inter.CoordLocal.X * {{4 + version % 7}});
        if ((band & 1) == 0)
          Util.ColorCopy(new double[] { 0.9, 0.3, {{version % 10}} / 10.0 }, inter.SurfaceColor);
        return band;
      }
    }
    scene.BackgroundColor = new double[] { 0.1, 0.2, 0.3 };
    scene.Camera = new StaticCamera(new Vector3d(0, 0, -5), new Vector3d(0, 0, 1), 50.0);
    scene.Sources = new LinkedList<ILightSource>();
    scene.Sources.Add(new AmbientLightSource(0.2));
    scene.Sources.Add(new PointLightSource(new Vector3d(-5, 4, -6), 1.0));
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 1, 1, 1 }, 0.1, 0.7, 0.2, 16));
    for (int i = 0; i < 3; i++)
    {
      var s = new Sphere();
      s.SetAttribute(PropertyName.TEXTURE, new Stripes{{version}}());
      root.InsertChild(s, Matrix4d.Scale(0.6) * Matrix4d.CreateTranslation(i - 1.0, 0, 0));
    }
    scene.Intersectable = root;
    context[PropertyName.CTX_WIDTH] = 160;
    context[PropertyName.CTX_HEIGHT] = 120;
    """);

  public static int Run(string[] args)
  {
    int renders = 200;
    string? csv = null;
    for (int i = 0; i < args.Length; i++)
    {
      if (args[i] == "--renders" && i + 1 < args.Length)
        renders = int.Parse(args[++i], CultureInfo.InvariantCulture);
      else if (args[i] == "--csv" && i + 1 < args.Length)
        csv = args[++i];
      else
      {
        Console.Error.WriteLine($"soak: unknown argument '{args[i]}' (use --renders N, --csv FILE)");
        return 2;
      }
    }

    string dir = Directory.CreateTempSubdirectory("grcis-soak-").FullName;
    TextWriter output = csv != null ? new StreamWriter(csv) : Console.Out;
    try
    {
      string path = Path.Combine(dir, "Edited.cs");
      File.WriteAllText(path, Script(0));
      using var scripts = new GrCis.Scripting.ScriptHost();
      var catalog = new SceneCatalog(scripts);
      using var demo = new DemoController(catalog) { Selected = catalog.AddScriptFile(path) };
      demo.Settings = demo.Settings with { Threads = Environment.ProcessorCount };

      output.WriteLine("pattern,render,render_ms,managed_mib,working_set_mib,script_contexts,compilations");
      foreach (string pattern in new[] { "edited", "unchanged" })
      {
        for (int r = 1; r <= renders; r++)
        {
          if (pattern == "edited")
            File.WriteAllText(path, Script(r));
          var clock = Stopwatch.StartNew();
          RenderResult result = demo.RenderAsync().GetAwaiter().GetResult()
            ?? throw new InvalidOperationException("the soak script did not build");
          if (!result.Succeeded)
            throw new InvalidOperationException("render failed: " + result.Error?.Message);
          clock.Stop();
          long managed = FullCollect();
          long workingSet = Process.GetCurrentProcess().WorkingSet64;
          output.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"{pattern},{r},{clock.Elapsed.TotalMilliseconds:0},{managed / 1048576.0:0.0},{workingSet / 1048576.0:0.0},{LiveScriptContexts()},{scripts.CompilationCount}"));
          output.Flush();
        }
      }
      return 0;
    }
    finally
    {
      if (csv != null)
        output.Dispose();
      Directory.Delete(dir, recursive: true);
    }
  }

  static int LiveScriptContexts() =>
    AssemblyLoadContext.All.Count(c => c.Name != null && c.Name.StartsWith("GrCisScript", StringComparison.Ordinal));

  static long FullCollect()
  {
    for (int i = 0; i < 3; i++)
    {
      GC.Collect();
      GC.WaitForPendingFinalizers();
    }
    return GC.GetTotalMemory(forceFullCollection: true);
  }
}
