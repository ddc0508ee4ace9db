using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Globalization;
using System.Text.Json;
using GrCis.Cli.Bench;
using GrCis.Cli.Jobs;
using Rendering;

namespace GrCis.Cli.Commands;

/// <summary>
/// <c>grcis bench [--json] [--quick] [--scene ID] [--threads N] [--no-slow] [--scaling] [--mesh FILE]</c>: the scene
/// suite, printing seconds, rays per second and the speedup over <c>--accel none</c> measured in the same run.
/// </summary>
public static class BenchCommand
{
  public static Command Build(CliEnvironment env)
  {
    var json = new Option<bool>("--json") { Description = "Print the results as JSON on stdout (progress stays on stderr)" };
    var quick = new Option<bool>("--quick") { Description = "A tiny configuration that runs in seconds (CI)" };
    var scene = new Option<string[]>("--scene")
    {
      Description = "Only cases whose id or name contains this text (repeatable); ids: five-balls, sphere-flake, flake9, mesh-10k, mesh-1m, two-spheres-720p …",
      AllowMultipleArgumentsPerToken = false,
    };
    var threads = new Option<int>("--threads", "-t") { Description = "Worker threads; 0 = one per processor", DefaultValueFactory = _ => 0 };
    var noSlow = new Option<bool>("--no-slow") { Description = "Skip the faithful path (no speedup column)" };
    var size = new Option<string?>("--size", "-s") { Description = "Override every case's image size (WxH)", HelpName = "WxH" };
    var spp = new Option<int?>("--spp") { Description = "Override every case's samples per pixel" };
    var scaling = new Option<bool>("--scaling")
    {
      Description = "Also time each case's fast path on 1 thread vs --threads (alternated, best of 2) and this machine's own parallel ceiling",
    };
    var mesh = new Option<string?>("--mesh") { Description = "Also bench this OBJ mesh (.obj or .obj.gz), e.g. the Utah teapot", HelpName = "file" };

    var cmd = new Command("bench", "Benchmark the scene suite: seconds, rays/s, speedup over --accel none")
    {
      json, quick, scene, threads, noSlow, scaling, mesh, size, spp,
    };
    cmd.SetAction(parse =>
    {
      int t = parse.GetValue(threads);
      if (t < 0)
        throw new UsageException($"invalid --threads {t}: must be 0 (one per processor) or more");
      int effective = Rendering.Execution.RenderDefaults.Threads(t);
      string? meshFile = parse.GetValue(mesh);
      if (meshFile != null)
        meshFile = System.IO.Path.GetFullPath(meshFile, env.WorkingDirectory);
      if (meshFile != null && !System.IO.File.Exists(meshFile))
        throw new UsageException($"--mesh '{meshFile}': no such file");
      if (meshFile != null)
        BenchSuite.ReadObj(meshFile);   // a bad file fails now, naming its line, not after minutes of other cases
      string[] filters = parse.GetValue(scene) ?? Array.Empty<string>();

      string? sizeText = parse.GetValue(size);
      ImageSize? sizeOverride = sizeText != null ? ImageSize.Parse(sizeText) : null;
      int? sppOverride = parse.GetValue(spp);
      if (sppOverride is < 1)
        throw new UsageException($"invalid --spp {sppOverride}: must be at least 1");
      IReadOnlyList<BenchCase> suite = BenchSuite.Create(parse.GetValue(quick), meshFile);
      var cases = new List<BenchCase>();
      foreach (BenchCase c in suite)
        if (Matches(c, filters, suite))
          cases.Add(c with { Size = sizeOverride ?? c.Size, Spp = sppOverride ?? c.Spp });
      if (cases.Count == 0)
        throw new UsageException($"--scene matched no bench case");

      bool asJson = parse.GetValue(json);
      bool skipSlow = parse.GetValue(noSlow);
      env.Error.WriteLine(string.Create(CultureInfo.InvariantCulture,
        $"grcis bench: {cases.Count} cases, {effective} thread{(effective == 1 ? "" : "s")}; speedup = fast rays/s ÷ faithful (--accel none) rays/s, the faithful path rendered at the small size shown"));
      bool measureScaling = parse.GetValue(scaling);
      double? ceiling = null;
      if (measureScaling)
      {
        ceiling = ParallelCeiling.Measure(effective);
        env.Error.WriteLine(string.Create(CultureInfo.InvariantCulture,
          $"grcis bench: this machine's {effective}-thread ceiling (register-only arithmetic, throughput vs 1 thread): {ceiling:0.00}×"));
      }
      var results = new List<BenchResult>();
      foreach (BenchCase c in cases)
      {
        if (env.Cancel.IsCancellationRequested)
          break;
        IRayScene built = c.Build();
        BenchResult r = BenchSuite.Run(c, built, effective, skipSlow, env.Cancel);
        if (measureScaling)
          r = ThreadScaling.Measure(r, c, built, effective, rounds: 2, env.Cancel) with { ScalingCeiling = ceiling };
        results.Add(r);
        (asJson ? env.Error : env.Out).WriteLine(Line(r));
      }
      if (env.Cancel.IsCancellationRequested)
      {
        env.Error.WriteLine("grcis: error: cancelled");
        return ExitCodes.Cancelled;
      }
      if (asJson)
        env.Out.WriteLine(JsonSerializer.Serialize(results, new JsonSerializerOptions { WriteIndented = true, PropertyNamingPolicy = JsonNamingPolicy.CamelCase }));
      return ExitCodes.Success;
    });
    return cmd;
  }

  /// <summary>A filter equal to a case id selects that case only; otherwise it matches ids and names containing it.</summary>
  static bool Matches(BenchCase c, string[] filters, IReadOnlyList<BenchCase> suite)
  {
    if (filters.Length == 0)
      return true;
    foreach (string f in filters)
    {
      bool exact = false;
      foreach (BenchCase other in suite)
        exact |= other.Id.Equals(f, StringComparison.OrdinalIgnoreCase);
      if (exact ? c.Id.Equals(f, StringComparison.OrdinalIgnoreCase)
                : c.Id.Contains(f, StringComparison.OrdinalIgnoreCase) || c.Name.Contains(f, StringComparison.OrdinalIgnoreCase))
        return true;
    }
    return false;
  }

  static string Line(BenchResult r)
  {
    string s = string.Create(CultureInfo.InvariantCulture,
      $"{r.Name,-34} {r.Size,9} {r.Spp,2} spp  {r.Seconds,8:0.000} s (cpu {r.CpuSeconds,7:0.000} s)  {r.RaysPerSecond / 1e6,7:0.00} Mrays/s  prep {r.PrepareSeconds:0.00} s");
    if (r.Speedup is double sp)
      s += string.Create(CultureInfo.InvariantCulture,
        $"  none@{r.SlowSize} {r.SlowSpp}spp {r.SlowSeconds:0.00} s {r.SlowRaysPerSecond:0.###e+0} rays/s  speedup {sp:#,0.0}×");
    if (r.Scaling is double sc)
      s += string.Create(CultureInfo.InvariantCulture,
        $"  1→{r.Threads} threads {r.OneThreadSeconds:0.000}→{r.ThreadsSeconds:0.000} s = {sc:0.00}× (machine {r.ScalingCeiling:0.00}×)");
    if (r.Fallbacks > 0)
      s += string.Create(CultureInfo.InvariantCulture, $"  fallbacks {r.Fallbacks}");
    if (r.Description.Length > 0)
      s += "  (" + r.Description + ")";
    return s;
  }
}
