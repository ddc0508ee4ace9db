using System.Collections.Generic;
using System.IO;
using Rendering.Imaging;

namespace GrCis.Cli.Tests;

/// <summary>
/// Students' modules and scripts from earlier GrCis years through <c>grcis render</c>: a failed
/// <c>Debug.Assert</c> warns and goes on, an exception in module code names its file and line (the full
/// stack on request), a still never calls a student's <c>Clone()</c>, and a student's tracer finds its
/// <c>scene</c> field set.
/// </summary>
public class StudentCodeTests
{
  const string Halving = """
    using System.Diagnostics;

    namespace Checks
    {
      public static class Build
      {
        public static int Half (int n)
        {
          Debug.Assert(n % 2 == 0, "n must be even");
          Trace.Assert(n > 100, "n must be big");
          return n / 2;
        }
      }
    }
    """;

  [Fact]
  public void A_failed_Debug_Assert_in_a_module_is_a_warning_naming_its_line_once_and_the_image_is_written()
  {
    using var dir = new TempDirectory();
    Directory.CreateDirectory(dir.File("mod"));
    File.WriteAllText(dir.File("mod/Checks.cs"), Halving);
    File.WriteAllText(dir.File("scene.cs"), ScriptCommandTests.SceneBody + """
      context["half"] = Checks.Build.Half(7) + Checks.Build.Half(9);
      """);

    // A real process: .NET ends it at a failed assertion unless grcis handles it (a test host would hide that).
    (int code, _, string error) = GrcisProcess.Run(dir.Path, "render", "scene.cs", "--module", "mod", "--size", "16x12", "-o", "out.png", "-q");

    Assert.True(code == 0, error);
    Assert.True(File.Exists(dir.File("out.png")));
    string checks = Path.Combine(dir.Path, "mod", "Checks.cs");
    Assert.Contains($"{checks}(9): warning GRCIS006: assertion failed: n must be even", error);
    Assert.Contains($"{checks}(10): warning GRCIS006: assertion failed: n must be big", error);
    Assert.Single(error.Split('\n'), l => l.Contains("(9): warning GRCIS006", System.StringComparison.Ordinal));
  }

  const string BrokenTexture = """
    using Rendering;

    namespace Textures2020
    {
      public class Broken : ITexture
      {
        public long Apply (Intersection inter)
        {
          if (inter.T > 0.0)
            throw new System.InvalidOperationException("texture table not loaded");
          return 0L;
        }
      }
    }
    """;

  /// <summary>A folder with the module <c>tex</c> and <c>scene.cs</c>, whose texture throws on every hit.</summary>
  static TempDirectory SceneWithBrokenTexture()
  {
    var dir = new TempDirectory();
    Directory.CreateDirectory(dir.File("tex"));
    File.WriteAllText(dir.File("tex/Broken.cs"), BrokenTexture);
    File.WriteAllText(dir.File("scene.cs"), ScriptCommandTests.SceneBody + """
      root.SetAttribute(PropertyName.TEXTURE, new Textures2020.Broken());
      """);
    return dir;
  }

  [Fact]
  public void An_exception_in_module_code_while_rendering_is_one_line_naming_the_module_file_and_line()
  {
    using TempDirectory dir = SceneWithBrokenTexture();

    CliRun run = CliRun.Of(dir.Path, "render", "scene.cs", "--module", "tex", "--size", "16x12", "-o", "out.png", "-q");

    Assert.Equal(ExitCodes.Failure, run.ExitCode);
    string line = Assert.Single(run.ErrorLines);
    Assert.StartsWith($"grcis: error: {Path.Combine(dir.Path, "tex", "Broken.cs")}(10,", line);
    Assert.EndsWith("runtime error: InvalidOperationException: texture table not loaded", line);
    Assert.DoesNotContain("render failed", line);
    Assert.False(File.Exists(dir.File("out.png")));
  }

  [Fact]
  public void GRCIS_STACKTRACE_prints_the_whole_exception_after_the_errors_line()
  {
    using TempDirectory dir = SceneWithBrokenTexture();

    (int code, _, string error) = GrcisProcess.Run(dir.Path, new Dictionary<string, string> { ["GRCIS_STACKTRACE"] = "1" },
      "render", "scene.cs", "--module", "tex", "--size", "16x12", "-o", "out.png", "-q");

    Assert.Equal(ExitCodes.Failure, code);
    Assert.Contains("runtime error: InvalidOperationException: texture table not loaded", error);
    // The stack names the module method and the renderer frames below it.
    Assert.Contains("at Textures2020.Broken.Apply(Intersection inter) in ", error);
    Assert.Contains("Broken.cs:line 10", error);
  }

  [Fact]
  public void A_still_never_clones_a_students_animated_node_and_a_students_tracer_finds_its_scene_field_set()
  {
    using var dir = new TempDirectory();
    // A 2020-style script: an animated node whose Clone() is left unfinished, and a tracer reading 'scene'.
    File.WriteAllText(dir.File("scene.cs"), ScriptCommandTests.SceneBody + """
      var spinner = new Spinner();
      spinner.InsertChild(root, Matrix4d.Identity);
      scene.Intersectable = spinner;
      context[PropertyName.CTX_ALGORITHM] = new SceneReadingTracer();

      class Spinner : AnimatedCSGInnerNode
      {
        public Spinner () : base(SetOperation.Union) { }
        public override object Clone () => throw new System.NotImplementedException("Clone is homework for next week");
      }

      class SceneReadingTracer : RayTracing
      {
        public override long GetSample (double x, double y, double[] color)
        {
          // GrCis's RayTracing kept its scene in this protected field.
          if (scene == null)
            throw new System.InvalidOperationException("scene is null");
          return base.GetSample(x, y, color);
        }
      }
      """);

    CliRun run = CliRun.Of(dir.Path, "render", "scene.cs", "--size", "32x24", "--threads", "2", "-o", "out.png", "-q");

    Assert.True(run.ExitCode == 0, run.Error);
    Rgb8Image image = PngFile.Load(dir.File("out.png"));
    Assert.Equal(32, image.Width);
  }
}
