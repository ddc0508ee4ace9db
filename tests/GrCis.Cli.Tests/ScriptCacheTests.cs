using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using GrCis.Scripting.Caching;
using GrCis.TestSupport;

namespace GrCis.Cli.Tests;

/// <summary>
/// <c>grcis</c> keeps compiled scene scripts between runs (GrCis.Scripting's ScriptCache): a second run of an
/// unchanged script loads it instead of compiling, and writes the same bytes; <c>--no-cache</c> and
/// <c>GRCIS_NO_CACHE=1</c> bypass it; processes rendering one script at once share it safely.
/// </summary>
public class ScriptCacheTests
{
  const string Script = """
    scene.Camera = new StaticCamera(new Vector3d(0.0, 0.0, -10.0), new Vector3d(0.0, 0.0, 1.0), 40.0);
    scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
    scene.Sources.Add(new PointLightSource(new Vector3d(-5.0, 3.0, -3.0), 1.0));
    Sphere s = new Sphere();
    s.SetAttribute(PropertyName.COLOR, new double[] { 1.0, 0.6, 0.0 });
    scene.Intersectable = s;
    if (param == "throw")
    {
      for (int i = 0; i < 3; i++) { int[] a = new int[2]; a[i] = i; }
    }
    """;

  static CliRun Run(string dir, ScriptCache? cache, params string[] args)
  {
    var output = new StringWriter();
    var error = new StringWriter();
    int code = Program.Run(args, new CliEnvironment(output, error) { WorkingDirectory = dir, ScriptCache = cache });
    return new CliRun(code, output.ToString(), error.ToString());
  }

  static string[] Entries(string cacheDir) =>
    Directory.Exists(cacheDir) ? Directory.GetFiles(cacheDir, "*" + ScriptCache.EntryExtension) : [];

  [Fact]
  public void A_second_render_of_an_unchanged_script_loads_it_from_the_cache_and_writes_the_same_bytes()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("ball.cs"), Script);
    string cacheDir = dir.File("cache");
    string[] render = ["render", "ball.cs", "--size", "40x30", "--spp", "4", "-q"];

    var first = new ScriptCache(cacheDir);
    Assert.Equal(0, Run(dir.Path, first, [.. render, "-o", "first.png"]).ExitCode);
    Assert.Equal((0, 1, 1), (first.Hits, first.Misses, first.Stores));

    var second = new ScriptCache(cacheDir);
    Assert.Equal(0, Run(dir.Path, second, [.. render, "-o", "second.png"]).ExitCode);
    Assert.Equal((1, 0, 0), (second.Hits, second.Misses, second.Stores));

    File.AppendAllText(dir.File("ball.cs"), "// edited\n");
    var edited = new ScriptCache(cacheDir);
    Assert.Equal(0, Run(dir.Path, edited, [.. render, "-o", "edited.png"]).ExitCode);
    Assert.Equal((0, 1, 1), (edited.Hits, edited.Misses, edited.Stores));

    Assert.Equal(File.ReadAllBytes(dir.File("first.png")), File.ReadAllBytes(dir.File("second.png")));
    Assert.Equal(File.ReadAllBytes(dir.File("first.png")), File.ReadAllBytes(dir.File("edited.png")));
  }

  [Theory]
  [InlineData("render")]
  [InlineData("animate")]
  [InlineData("info")]
  public void No_cache_compiles_afresh_and_neither_reads_nor_writes_the_cache(string command)
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("ball.cs"), Script);
    string cacheDir = dir.File("cache");
    string[] args = command switch
    {
      "render" => ["render", "ball.cs", "--size", "16x12", "-q", "-o", "out.png", "--no-cache"],
      "animate" => ["animate", "ball.cs", "--size", "16x12", "--frames", "0-0", "-q", "-o", "f####.png", "--no-cache"],
      _ => ["info", "ball.cs", "--no-cache"],
    };
    // A cache holding the script already: --no-cache does not even look.
    Assert.Equal(0, Run(dir.Path, new ScriptCache(cacheDir), "info", "ball.cs").ExitCode);
    string entry = Assert.Single(Entries(cacheDir));
    System.DateTime written = File.GetLastWriteTimeUtc(entry);

    var cache = new ScriptCache(cacheDir);
    CliRun run = Run(dir.Path, cache, args);
    Assert.True(run.ExitCode == 0, run.Error);
    Assert.Equal((0, 0, 0), (cache.Hits, cache.Misses, cache.Stores));
    Assert.Equal(written, File.GetLastWriteTimeUtc(Assert.Single(Entries(cacheDir))));
  }

  [Fact]
  public void A_runtime_error_names_the_same_line_and_column_from_the_cache()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("ball.cs"), Script);
    string cacheDir = dir.File("cache");
    string[] args = ["render", "ball.cs", "--size", "16x12", "-q", "-o", "out.png", "--param", "throw"];

    var first = new ScriptCache(cacheDir);
    CliRun fresh = Run(dir.Path, first, args);
    var second = new ScriptCache(cacheDir);
    CliRun cached = Run(dir.Path, second, args);

    Assert.Equal((1, 1), (first.Stores, second.Hits));
    Assert.Equal(ExitCodes.Failure, fresh.ExitCode);
    int column = Script.Split('\n')[8].IndexOf("a[i]", System.StringComparison.Ordinal) + 1;
    Assert.Contains($"ball.cs(9,{column}): runtime error: IndexOutOfRangeException", fresh.Error);
    Assert.Equal(fresh.Error, cached.Error);
    Assert.False(File.Exists(dir.File("out.png")));
  }

  [Theory]
  [InlineData("TexturedTorus.cs")]
  [InlineData("Panorama.cs")]
  [InlineData("MeshVase.cs")]
  public void A_script_of_the_scripts_folder_renders_the_same_pixels_from_the_cache(string script)
  {
    using var dir = new TempDirectory();
    string cacheDir = dir.File("cache");
    string[] render = ["render", RepoPaths.Script(script), "--size", "48x36", "--spp", "4", "--seed", "5", "-t", "2", "-q"];
    Assert.Equal(0, Run(dir.Path, null, [.. render, "-o", "fresh.pfm"]).ExitCode);
    Assert.Equal(0, Run(dir.Path, new ScriptCache(cacheDir), [.. render, "-o", "stored.pfm"]).ExitCode);
    var cache = new ScriptCache(cacheDir);
    Assert.Equal(0, Run(dir.Path, cache, [.. render, "-o", "cached.pfm"]).ExitCode);
    Assert.Equal(1, cache.Hits);
    Assert.Equal(File.ReadAllBytes(dir.File("fresh.pfm")), File.ReadAllBytes(dir.File("cached.pfm")));
    Assert.Equal(File.ReadAllBytes(dir.File("fresh.pfm")), File.ReadAllBytes(dir.File("stored.pfm")));
  }

  [Fact]
  public void Two_processes_rendering_one_script_at_once_both_succeed_and_share_one_entry()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("ball.cs"), Script);
    string cacheDir = dir.File("cache");
    var env = new Dictionary<string, string> { [ScriptCache.DirectoryVariable] = cacheDir };
    using Process a = GrcisProcess.Start(dir.Path, env, "render", "ball.cs", "--size", "40x30", "-q", "-o", "a.png");
    using Process b = GrcisProcess.Start(dir.Path, env, "render", "ball.cs", "--size", "40x30", "-q", "-o", "b.png");
    var ra = GrcisProcess.Finish(a);
    var rb = GrcisProcess.Finish(b);
    Assert.True(ra.Code == 0, ra.Error);
    Assert.True(rb.Code == 0, rb.Error);
    Assert.Equal(File.ReadAllBytes(dir.File("a.png")), File.ReadAllBytes(dir.File("b.png")));
    Assert.Single(Entries(cacheDir));
    Assert.DoesNotContain(Directory.GetFiles(cacheDir), f => !f.EndsWith(ScriptCache.EntryExtension, System.StringComparison.Ordinal) &&
                                                              Path.GetFileName(f) != ScriptCache.KeyFileName);
  }

  [Fact]
  public void A_cached_run_loads_no_compiler_assembly()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("ball.cs"), Script);
    Directory.CreateDirectory(dir.File("mod"));
    File.WriteAllText(dir.File("mod/Sizes.cs"), "namespace Mod { public static class Sizes { public static int Width => 24; } }\n");
    File.AppendAllText(dir.File("ball.cs"), "context[\"w\"] = Mod.Sizes.Width;\n");

    string[] Loaded(params string[] extra)
    {
      string list = dir.File("loaded.txt");
      File.Delete(list);
      var env = new Dictionary<string, string>
      {
        [ScriptCache.DirectoryVariable] = dir.File("cache"),
        ["DOTNET_STARTUP_HOOKS"] = typeof(StartupHook).Assembly.Location,
        [StartupHook.FileVariable] = list,
      };
      var r = GrcisProcess.Run(dir.Path, env, ["render", "ball.cs", "-m", "mod", "--size", "24x18", "-q", "-o", "out.png", .. extra]);
      Assert.True(r.Code == 0, r.Error);
      return File.ReadAllLines(list);
    }

    string[] first = Loaded();
    Assert.Contains("Microsoft.CodeAnalysis.CSharp", first);
    string[] cached = Loaded();
    Assert.Contains("GrCis.Scripting", cached);
    Assert.Contains(cached, a => a.StartsWith("GrCisModule_", System.StringComparison.Ordinal));
    Assert.DoesNotContain(cached, a => a.StartsWith("Microsoft.CodeAnalysis", System.StringComparison.Ordinal));
    Assert.Contains("Microsoft.CodeAnalysis", Loaded("--no-cache"));
  }

  [Fact]
  public void The_environment_chooses_the_folder_or_turns_the_cache_off()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("ball.cs"), Script);
    string cacheDir = dir.File("cache");
    var off = new Dictionary<string, string> { [ScriptCache.DirectoryVariable] = cacheDir, [ScriptCache.DisableVariable] = "1" };
    var r = GrcisProcess.Run(dir.Path, off, "info", "ball.cs");
    Assert.True(r.Code == 0, r.Error);
    Assert.Empty(Entries(cacheDir));

    var on = new Dictionary<string, string> { [ScriptCache.DirectoryVariable] = cacheDir };
    r = GrcisProcess.Run(dir.Path, on, "info", "ball.cs");
    Assert.True(r.Code == 0, r.Error);
    Assert.Single(Entries(cacheDir));
  }

  [Fact]
  public void Tests_keep_compiled_scripts_out_of_the_users_cache_folder()
  {
    Assert.Equal(TestScriptCache.Folder, ScriptCache.DefaultDirectory());
    Assert.Equal(TestScriptCache.Folder, new CliEnvironment(new StringWriter(), new StringWriter()).ScriptCache!.Directory);
  }
}
