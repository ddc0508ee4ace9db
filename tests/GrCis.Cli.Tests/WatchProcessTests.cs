using System;
using System.IO;
using System.Linq;
using System.Threading;
using Rendering.Imaging;

namespace GrCis.Cli.Tests;

/// <summary>
/// <c>grcis render --watch</c> and <c>grcis animate --watch</c> as a student uses them: one process renders, then renders
/// again after each save of the script, of a module file or of a data file the script read; a script that does not
/// compile prints its errors with file and line and leaves the last good image; Ctrl+C or SIGTERM ends the loop with 130.
/// </summary>
public class WatchProcessTests
{
  /// <summary>A sphere before a background whose red is <paramref name="red"/> (the top-left pixel shows it).</summary>
  static string Scene(string red, string prefix = "") => prefix + $$"""
    var root = new CSGInnerNode(SetOperation.Union);
    root.InsertChild(new Sphere(), Matrix4d.Identity);
    scene.Intersectable = root;
    scene.Camera = new StaticCamera(new Vector3d(0, 0, -5), new Vector3d(0, 0, 1), 40.0);
    scene.Sources = new LinkedList<ILightSource>();
    scene.BackgroundColor = new double[] { {{red}}, 0.2, 0.3 };
    """;

  /// <summary>The red of the top-left pixel (display-encoded: 0.1 is about 90, 0.9 about 240).</summary>
  static byte Red(string png) => PngFile.Load(png).Data[0];

  /// <summary>Writes as an editor's save does: the whole file anew.</summary>
  static void Save(string path, string text) => File.WriteAllText(path, text.Replace("\r\n", "\n"));

  [UnixFact]
  public void Script_edit_renders_a_new_image_in_the_same_process()
  {
    using var dir = new TempDirectory();
    string script = dir.File("s.cs");
    Save(script, Scene("0.1"));
    using var grcis = new WatchedProcess(dir.Path, "render", "s.cs", "-o", "out.png", "--size", "16x12", "--watch");
    grcis.WaitForPasses(1, 1);
    Assert.InRange(Red(dir.File("out.png")), 0, 120);

    Save(script, Scene("0.9"));
    grcis.WaitForPasses(2, 2);
    Assert.InRange(Red(dir.File("out.png")), 200, 255);
    // A save is several file events: they make one render, not one each.
    Thread.Sleep(1000);
    Assert.Equal(2, grcis.Passes);
    Assert.Equal(2, grcis.Images);
    Assert.Equal(ExitCodes.Cancelled, grcis.Signal("INT"));
  }

  [UnixFact]
  public void Module_edit_renders_a_new_image()
  {
    using var dir = new TempDirectory();
    Directory.CreateDirectory(dir.File("mods"));
    string module = dir.File("mods/Palette.cs");
    Save(module, "namespace Course;\npublic static class Palette { public static double Red => 0.1; }\n");
    Save(dir.File("s.cs"), Scene("Palette.Red", "using Course;\n"));
    using var grcis = new WatchedProcess(dir.Path, "render", "s.cs", "--module", "mods", "-o", "out.png", "--size", "16x12", "--watch");
    grcis.WaitForPasses(1, 1);
    Assert.InRange(Red(dir.File("out.png")), 0, 120);

    Save(module, "namespace Course;\npublic static class Palette { public static double Red => 0.9; }\n");
    grcis.WaitForPasses(2, 2);
    Assert.InRange(Red(dir.File("out.png")), 200, 255);
    Assert.Equal(ExitCodes.Cancelled, grcis.Signal("INT"));
  }

  [UnixFact]
  public void Data_file_the_script_read_is_watched()
  {
    using var dir = new TempDirectory();
    Directory.CreateDirectory(dir.File("data"));
    Save(dir.File("data/red.txt"), "0.1");
    Save(dir.File("s.cs"), Scene("double.Parse(File.ReadAllText(\"data/red.txt\"), System.Globalization.CultureInfo.InvariantCulture)",
                                 "using System.IO;\n"));
    using var grcis = new WatchedProcess(dir.Path, "render", "s.cs", "-o", "out.png", "--size", "16x12", "--watch");
    grcis.WaitForPasses(1, 1);
    Assert.InRange(Red(dir.File("out.png")), 0, 120);

    Save(dir.File("data/red.txt"), "0.9");
    grcis.WaitForPasses(2, 2);
    Assert.InRange(Red(dir.File("out.png")), 200, 255);
    Assert.Equal(ExitCodes.Cancelled, grcis.Signal("INT"));
  }

  [UnixFact]
  public void Compile_error_keeps_the_last_good_image_and_the_fix_renders_again()
  {
    using var dir = new TempDirectory();
    string script = dir.File("s.cs");
    Save(script, Scene("0.1"));
    using var grcis = new WatchedProcess(dir.Path, "render", "s.cs", "-o", "out.png", "--size", "16x12", "--watch");
    grcis.WaitForPasses(1, 1);
    byte[] good = File.ReadAllBytes(dir.File("out.png"));

    // Line 3 loses its semicolon.
    Save(script, Scene("0.9").Replace("scene.Intersectable = root;", "scene.Intersectable = root", StringComparison.Ordinal));
    grcis.WaitForPasses(2, 1);
    Assert.Contains(script + "(3,", grcis.Error);
    Assert.Contains("error CS1002", grcis.Error);
    Assert.Contains($"grcis: error: scene script '{script}' did not compile", grcis.Error);
    Assert.Equal(1, grcis.Images);
    Assert.Equal(good, File.ReadAllBytes(dir.File("out.png")));

    Save(script, Scene("0.9"));
    grcis.WaitForPasses(3, 2);
    Assert.Equal(2, grcis.Images);
    Assert.InRange(Red(dir.File("out.png")), 200, 255);
    Assert.Equal(ExitCodes.Cancelled, grcis.Signal("INT"));
  }

  [UnixFact]
  public void Animate_watch_renders_the_first_frame_again_after_an_edit()
  {
    using var dir = new TempDirectory();
    string script = dir.File("s.cs");
    Save(script, Scene("0.1"));
    using var grcis = new WatchedProcess(dir.Path, "animate", "s.cs", "-o", "f####.png", "--size", "16x12", "--watch");
    grcis.WaitForPasses(1, 1);
    Assert.InRange(Red(dir.File("f0000.png")), 0, 120);
    Assert.False(File.Exists(dir.File("f0001.png")), "--watch renders only the first frame without --frames");

    Save(script, Scene("0.9"));
    grcis.WaitForPasses(2, 2);
    Assert.Equal(2, grcis.Images);
    Assert.InRange(Red(dir.File("f0000.png")), 200, 255);
    Assert.Equal(ExitCodes.Cancelled, grcis.Signal("INT"));
  }

  [UnixTheory]
  [InlineData("INT")]
  [InlineData("TERM")]
  public void Ctrl_c_and_sigterm_end_the_loop_with_130_and_leave_no_temporary_file(string signal)
  {
    using var dir = new TempDirectory();
    Save(dir.File("s.cs"), Scene("0.1"));
    using var grcis = new WatchedProcess(dir.Path, "render", "s.cs", "-o", "out.png", "--size", "16x12", "--watch");
    grcis.WaitForPasses(1, 1);

    Assert.Equal(ExitCodes.Cancelled, grcis.Signal(signal));
    Assert.Contains("grcis: stopped watching", grcis.Error);
    Assert.Equal(["out.png", "s.cs"], dir.AllFiles().Select(Path.GetFileName).Order(StringComparer.Ordinal).ToArray());
  }

  [Fact]
  public void Watch_of_a_built_in_scene_is_a_usage_error()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", "Five balls", "-o", "x.png", "--watch");
    Assert.Equal(ExitCodes.Usage, run.ExitCode);
    Assert.Contains("--watch needs a scene script", run.Error);
    Assert.Empty(dir.AllFiles());
  }
}
