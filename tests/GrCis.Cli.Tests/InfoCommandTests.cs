using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using GrCis.Cli.Animation;
using GrCis.Cli.SceneSources;
using GrCis.Hosting;

namespace GrCis.Cli.Tests;

/// <summary><c>grcis info</c>: tooltip, size, supersampling, animation range, algorithm and synthesizer.</summary>
public class InfoCommandTests
{
  static string Value(CliRun run, string key) =>
    run.Out.Split('\n').Select(l => l.TrimEnd('\r')).Single(l => l.StartsWith(key + ":", System.StringComparison.Ordinal))[(key.Length + 1)..].Trim();

  [Fact]
  public void Info_on_a_parameterised_script_shows_tooltip_size_and_supersampling_from_the_script()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "info", RepoPaths.Script("Spiral.cs"), "--param", "count=5");

    Assert.Equal(0, run.ExitCode);
    Assert.Equal(RepoPaths.Script("Spiral.cs"), Value(run, "scene"));
    Assert.StartsWith("count=<int> (balls, default 24), turns=<double>", Value(run, "parameters"));
    Assert.Equal("count=5", Value(run, "param"));
    Assert.Equal("480x360 (script)", Value(run, "size"));
    Assert.Equal("4 (script)", Value(run, "supersampling"));
    Assert.Equal("none (a still scene)", Value(run, "animation"));
    Assert.Equal("RayTracing (default)", Value(run, "algorithm"));
    Assert.StartsWith("SimpleImageSynthesizer (default", Value(run, "synthesizer"));
    Assert.Equal("", run.Error);
    Assert.Empty(dir.AllFiles());
  }

  [Fact]
  public void Info_on_an_animated_script_shows_the_range_fps_and_frame_count()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "info", RepoPaths.Script("Orbit.cs"));

    Assert.Equal(0, run.ExitCode);
    // Frames at 0, 1/12, …, 4 s: 4 · 12 + 1.
    Assert.Equal("start 0 s, end 4 s, 12 fps, 49 frames", Value(run, "animation"));
    Assert.Equal("640x480 (default)", Value(run, "size"));
    Assert.Equal("1 (default)", Value(run, "supersampling"));
  }

  [Fact]
  public void Info_names_the_scripts_algorithm_and_synthesizer_types()
  {
    using var dir = new TempDirectory();
    string s = dir.File("s.cs");
    System.IO.File.WriteAllText(s, ScriptCommandTests.SceneBody +
      "context[PropertyName.CTX_ALGORITHM] = new RayCasting();\ncontext[PropertyName.CTX_SYNTHESIZER] = new SupersamplingImageSynthesizer();\n");
    CliRun run = CliRun.Of(dir.Path, "info", s);

    Assert.Equal(0, run.ExitCode);
    Assert.Equal("RayCasting (script)", Value(run, "algorithm"));
    Assert.Equal("SupersamplingImageSynthesizer (script)", Value(run, "synthesizer"));
    Assert.Equal("(no tooltip)", Value(run, "parameters"));
  }

  [Fact]
  public void Info_on_a_builtin_scene()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "info", "two spheres");

    Assert.Equal(0, run.ExitCode);
    Assert.Equal("Two spheres (built-in)", Value(run, "scene"));
    Assert.StartsWith("n=<double>", Value(run, "parameters"));
    Assert.Equal("640x480 (default)", Value(run, "size"));
    Assert.Equal("none (a still scene)", Value(run, "animation"));

    CliRun plain = CliRun.Of(dir.Path, "info", "Five balls");
    Assert.Equal("(none)", Value(plain, "parameters"));
  }

  [Fact]
  public void Info_on_an_unknown_scene_is_a_usage_error()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "info", "five bals");
    Assert.Equal(ExitCodes.Usage, run.ExitCode);
    Assert.Contains("did you mean 'Five balls'", run.Error);
  }

  public static IEnumerable<object[]> Scripts() =>
    Directory.GetFiles(RepoPaths.Scripts, "*.cs").Select(Path.GetFileName).OrderBy(f => f, StringComparer.Ordinal)
      .Select(f => new object[] { f! });

  [Theory]
  [MemberData(nameof(Scripts))]
  public void Info_reports_the_frames_animate_renders_for_every_script(string file)
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "info", RepoPaths.Script(file));
    Assert.Equal(0, run.ExitCode);
    string animation = Value(run, "animation");

    // What grcis animate renders without options: its plan over the prepared script.
    using var source = new ScriptSceneSource(RepoPaths.Script(file), "", Array.Empty<string>());
    PreparedRender prepared = new RenderRequest(source, new RenderSettings(), GivenSettings.None).Prepare();
    AnimationPlan plan = AnimationPlan.Create(null, null, null, prepared.Timing, prepared.Scene, null, ShardSpec.All);
    if (animation.StartsWith("none", StringComparison.Ordinal))
      Assert.False(Rendering.SceneCloner.IsTimeDependent(prepared.Scene), $"{file}: info calls an animated scene still");
    else
      Assert.EndsWith($", {plan.Frames.Count} frames", animation);
  }
}
