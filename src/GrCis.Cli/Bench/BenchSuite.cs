using Scene3D;
using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Threading;
using GrCis.Cli.Jobs;
using Rendering;
using Rendering.Accel;
using Rendering.Execution;
using GrCis.Hosting;

namespace GrCis.Cli.Bench;

/// <summary>
/// The scene suite of <c>grcis bench</c>: classic scenes at 640×480 16 spp, GrCis's Sphere flake, the
/// POV-Ray peer flake (9 children, depth 4), procedural torus meshes of 10k and 1M triangles (an OBJ mesh
/// with <c>--mesh</c>), Two spheres at 1280×720. Each case is prepared and JIT-warmed by 64×48 renders,
/// then timed once on the fast path and once on the faithful path at a small size.
/// </summary>
public static class BenchSuite
{
  static readonly ImageSize Vga = new(640, 480), Hd = new(1280, 720), Small = new(320, 240), Mini = new(160, 120), Tiny = new(64, 48), Micro = new(32, 24);

  public static IReadOnlyList<BenchCase> Create(bool quick, string? meshFile)
  {
    var cases = new List<BenchCase>();
    if (quick)
    {
      // CI: seconds, not minutes — tiny images, small meshes.
      cases.Add(new BenchCase("five-balls", "Five balls", () => Scenes.Create("Five balls"), new(48, 36), 1, new(24, 18), 1));
      cases.Add(new BenchCase("flake9", "Sphere flake 9×4 (POV-Ray peer)", () => Flake9(1), new(48, 36), 1, new(24, 18), 1) { Description = "depth 1: 10 spheres" });
      cases.Add(MeshCase("mesh-2k", "Torus mesh 2k", () => ProceduralMesh.TorusWithTriangles(2_000), true, new(48, 36), 1, new(24, 18)));
      if (meshFile != null)
        cases.Add(MeshCase("mesh-file", "Mesh " + System.IO.Path.GetFileName(meshFile), () => ReadObj(meshFile), false, new(48, 36), 1, new(24, 18)));
      return cases;
    }

    // The faithful path tests every solid and every triangle: the flakes and meshes get smaller images there.
    foreach (string name in Scenes.Names)
    {
      // GrCis's flake (2,801 spheres) is slow on the faithful path: a tinier image for it.
      bool flake = name == "Sphere flake";
      cases.Add(new BenchCase(Slug(name), name, () => Scenes.Create(name), Vga, 16, flake ? Tiny : Vga, 1)
      {
        Description = flake ? "2,801 spheres" : "",
      });
    }
    cases.Add(new BenchCase("flake9", "Sphere flake 9×4 (POV-Ray peer)", () => Flake9(4), Vga, 16, Tiny, 1) { Description = "7,381 spheres" });
    cases.Add(MeshCase("mesh-10k", "Torus mesh 10k", () => ProceduralMesh.Torus(100, 50), true, Vga, 16, Small) with { Description = "10,000 triangles" });
    cases.Add(MeshCase("mesh-1m", "Torus mesh 1M", () => ProceduralMesh.Torus(1000, 500), true, Vga, 16, Micro) with { Description = "1,000,000 triangles" });
    if (meshFile != null)
      cases.Add(MeshCase("mesh-file", "Mesh " + System.IO.Path.GetFileName(meshFile), () => ReadObj(meshFile), false, Vga, 16, Mini));
    cases.Add(new BenchCase("two-spheres-720p", "Two spheres 1280×720", () => Scenes.Create("Two spheres"), Hd, 16, Vga, 1));
    return cases;
  }

  /// <summary>The POV-Ray peer flake (sphereflake.pov) as a scene.</summary>
  public static IRayScene Flake9(int depth)
  {
    var sc = new DefaultRayScene();
    Scenes.SphereFlake9(sc, depth);
    return sc;
  }

  /// <summary>A mesh case: the mesh is made (or read) when the case is built; its triangle count is kept, the mesh is not.</summary>
  static BenchCase MeshCase(string id, string name, Func<SceneBrep> make, bool tilt, ImageSize size, int spp, ImageSize slowSize)
  {
    long triangles = 0;
    return new BenchCase(id, name, () =>
    {
      SceneBrep mesh = make();
      triangles = mesh.Triangles;
      var sc = new DefaultRayScene();
      Scenes.MeshScene(sc, mesh, tilt);
      return sc;
    }, size, spp, slowSize, 1)
    {
      Triangles = () => triangles,
    };
  }

  /// <summary>Reads the <c>--mesh</c> file; <see cref="Rendering.MeshFormatException"/> names its file and line.</summary>
  public static SceneBrep ReadObj(string path)
  {
    var mesh = new SceneBrep();
    new WavefrontObj().ReadBrep(path, mesh);
    return mesh;
  }

  public static string Slug(string name) => name.ToLowerInvariant().Replace(' ', '-');

  static readonly ImageSize WarmUpSize = new(64, 48);
  const double WarmUpSeconds = 1.0;
  const int WarmUpMaxPasses = 100;

  /// <summary>
  /// Renders one case, its scene built by the caller (fast path, then the faithful path unless
  /// <paramref name="skipSlow"/>); <c>--scaling</c> renders the same scene again.
  /// </summary>
  public static BenchResult Run(BenchCase c, IRayScene scene, int threads, bool skipSlow, CancellationToken cancel)
  {

    // Warm-up (timed as preparation, with the lazily built mesh BVHs): small real renders at the case's
    // samples per pixel for a second. The runtime moves a method to tier-1 code only after 100 ms without
    // new tier-0 JIT work and 30 further calls (twice with dynamic PGO), so the old single 8×6 render left
    // the timed render on tier-0 code for its first fraction of a second; 0.25 s of warm-up was still
    // measurably short (Five balls 0.87 vs 0.70 CPU s with DOTNET_TC_CallCountingDelayMs=0), 1 s is not.
    // "prep" reports the first pass only: scene preparation and mesh BVHs, plus that pass's JIT.
    var clock = Stopwatch.StartNew();
    double prepare = 0.0;
    for (int pass = 0; pass < WarmUpMaxPasses && !cancel.IsCancellationRequested; pass++)
    {
      Render(scene, WarmUpSize, c.Spp, threads, AccelMode.Bvh, cancel, out _);
      if (pass == 0)
        prepare = clock.Elapsed.TotalSeconds;
      else if (clock.Elapsed.TotalSeconds >= WarmUpSeconds)
        break;
    }

    TimeSpan cpu0 = Process.GetCurrentProcess().TotalProcessorTime;
    FrameResult fast = Render(scene, c.Size, c.Spp, threads, AccelMode.Bvh, cancel, out long fallbacks);
    double cpu = (Process.GetCurrentProcess().TotalProcessorTime - cpu0).TotalSeconds;
    var result = new BenchResult
    {
      Id = c.Id,
      Name = c.Name,
      Description = c.Description,
      Size = c.Size.ToString(),
      Spp = c.Spp,
      Triangles = c.Triangles?.Invoke(),
      Threads = threads,
      Seconds = fast.Statistics.Elapsed.TotalSeconds,
      CpuSeconds = cpu,
      Rays = fast.Statistics.Rays,
      RaysPerSecond = fast.Statistics.Rays / Math.Max(fast.Statistics.Elapsed.TotalSeconds, 1e-9),
      PrepareSeconds = prepare,
      Fallbacks = fallbacks,
    };
    if (skipSlow || cancel.IsCancellationRequested)
      return result;

    // Warm-up at the same small size first: a short faithful run would otherwise time tier-0 JIT code.
    Render(scene, c.SlowSize, c.SlowSpp, threads, AccelMode.None, cancel, out _);
    FrameResult slow = Render(scene, c.SlowSize, c.SlowSpp, threads, AccelMode.None, cancel, out _);
    double slowRate = slow.Statistics.Rays / Math.Max(slow.Statistics.Elapsed.TotalSeconds, 1e-9);
    return result with
    {
      SlowSize = c.SlowSize.ToString(),
      SlowSpp = c.SlowSpp,
      SlowSeconds = slow.Statistics.Elapsed.TotalSeconds,
      SlowRaysPerSecond = slowRate,
      Speedup = slowRate > 0.0 ? result.RaysPerSecond / slowRate : null,
    };
  }

  internal static FrameResult Render(IRayScene scene, ImageSize size, int spp, int threads, AccelMode accel, CancellationToken cancel, out long fallbacks)
  {
    var settings = new RenderSettings { Width = size.Width, Height = size.Height, SamplesPerPixel = spp, Threads = threads, Accel = accel }.Validate();
    ImageSynthesizer renderer = settings.CreateSynthesizer();
    RayTracing function = settings.CreateImageFunction(scene);
    FrameResult result = FrameRendering.Render(scene, function, renderer, settings.ToRenderOptions(), null, cancel);
    fallbacks = function.LastPrepared?.FallbackCount ?? 0;
    return result;
  }
}
