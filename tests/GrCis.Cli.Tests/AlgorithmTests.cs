using System;
using System.IO;
using System.Linq;
using Rendering.Imaging;

namespace GrCis.Cli.Tests;

/// <summary><c>--algorithm raytracing|distributed|path</c>: which image function renders, and how it meets a script's own choice.</summary>
public class AlgorithmTests
{
  static float[] Render(TempDirectory dir, string name, params string[] args)
  {
    CliRun run = CliRun.Of(dir.Path, new[] { "render" }.Concat(args).Concat(new[] { "-o", name, "--size", "32x24", "--threads", "2", "-q" }).ToArray());
    Assert.True(run.ExitCode == 0, run.Error);
    return PfmReader.Load(dir.File(name)).Data;
  }

  [Fact]
  public void Each_algorithm_renders_the_scene_its_own_way_and_raytracing_is_the_default()
  {
    using var dir = new TempDirectory();
    float[] plain = Render(dir, "a.pfm", "Test scene", "--spp", "4");
    float[] whitted = Render(dir, "b.pfm", "Test scene", "--spp", "4", "--algorithm", "raytracing");
    float[] distributed = Render(dir, "c.pfm", "Test scene", "--spp", "4", "--algorithm", "distributed");
    float[] path = Render(dir, "d.pfm", "Test scene", "--spp", "4", "-a", "path");
    Assert.Equal(plain, whitted);
    Assert.NotEqual(whitted, distributed);
    Assert.NotEqual(whitted, path);
    Assert.NotEqual(distributed, path);
  }

  [Fact]
  public void A_given_algorithm_replaces_the_scripts_choice_and_says_so()
  {
    using var dir = new TempDirectory();
    string script = Path.Combine(RepoPaths.Scripts, "SoftShadows.cs");
    CliRun run = CliRun.Of(dir.Path, "render", script, "--algorithm", "raytracing", "--size", "32x24", "--spp", "4", "-o", "x.pfm");
    Assert.Equal(0, run.ExitCode);
    Assert.Contains("DistributedRayTracing", run.Error);
    Assert.Contains("--algorithm", run.Error);
  }

  [Fact]
  public void An_unknown_algorithm_is_a_usage_error_naming_the_choices()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", "--algorithm", "radiosity", "-o", "x.png");
    Assert.Equal(ExitCodes.Usage, run.ExitCode);
    Assert.Contains("radiosity", run.Error);
    Assert.Contains("path", run.Error);
    Assert.Empty(dir.AllFiles());
  }
}
