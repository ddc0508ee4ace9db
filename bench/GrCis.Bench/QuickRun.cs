using System;
using System.Diagnostics;
using GrCis.Testing;
using Rendering;
using Rendering.Accel;
using Rendering.Execution;

namespace GrCis.Bench;

/// <summary>
/// Console timings of whole renders (not a unit test, not BenchmarkDotNet: one run each, after a warm-up).
/// The faithful path is timed on a smaller image and scaled by the pixel ratio, as it takes minutes.
/// </summary>
internal static class QuickRun
{
  public static int Run(string[] args)
  {
    int width = 640, height = 480, slowWidth = 64, slowHeight = 48;
    string sceneName = "flake9";
    for (int i = 0; i + 1 < args.Length; i += 2)
      switch (args[i])
      {
        case "--scene": sceneName = args[i + 1]; break;
        case "--size": (width, height) = ParseSize(args[i + 1]); break;
        case "--slow-size": (slowWidth, slowHeight) = ParseSize(args[i + 1]); break;
      }

    Func<IRayScene> build = sceneName switch
    {
      "flake9" => () => TestScenes.Flake9(4),
      "grcis-flake" => () => TestScenes.GrCisFlake(5),
      "five-balls" => TestScenes.FiveBalls,
      "two-spheres" => TestScenes.TwoSpheresGlass,
      "csg-mix" => TestScenes.CsgMix,
      _ => throw new ArgumentException($"Unknown scene '{sceneName}' (flake9, grcis-flake, five-balls, two-spheres, csg-mix)."),
    };

    IRayScene scene = build();
    var sw = Stopwatch.StartNew();
    PreparedScene ps = PreparedScene.Prepare(scene.Intersectable);
    double prepareMs = sw.Elapsed.TotalMilliseconds;
    Console.WriteLine($"scene {sceneName}: {ps.MemberCount} members ({ps.BoundedCount} in BVH, {ps.UnboundedCount} always tested, {ps.CsgMemberCount} CSG kernels, {ps.ListMemberCount} via LinkedList); prepare {prepareMs:F1} ms");

    // Warm up both paths (JIT) on a tiny image.
    Time(scene, AccelMode.Bvh, 32, 24);
    Time(scene, AccelMode.None, 16, 12);

    (double fast, long fastRays, long fastAlloc) = Time(scene, AccelMode.Bvh, width, height);
    (double slow, long slowRays, _) = Time(scene, AccelMode.None, slowWidth, slowHeight);
    double scale = (double)(width * height) / (slowWidth * slowHeight);
    double slowScaled = slow * scale;
    Console.WriteLine($"fast  {width}x{height} 1 spp 1 thread: {fast:F3} s, {fastRays / fast / 1e6:F2} Mrays/s, {(double)fastAlloc / (width * height):F0} B/pixel allocated");
    Console.WriteLine($"none  {slowWidth}x{slowHeight} 1 spp 1 thread: {slow:F3} s, {slowRays / slow / 1e6:F3} Mrays/s -> scaled to {width}x{height}: {slowScaled:F1} s");
    Console.WriteLine($"speedup fast / none: {slowScaled / fast:F0}x");
    return 0;
  }

  static (int, int) ParseSize(string s)
  {
    string[] p = s.Split('x');
    return (int.Parse(p[0]), int.Parse(p[1]));
  }

  static (double Seconds, long Rays, long Allocated) Time(IRayScene scene, AccelMode mode, int w, int h)
  {
    Intersection.countRays = 0;
    long alloc0 = GC.GetAllocatedBytesForCurrentThread();
    var sw = Stopwatch.StartNew();
    RenderHelper.Render(scene, mode, w, h);
    double s = sw.Elapsed.TotalSeconds;
    return (s, Intersection.countRays, GC.GetAllocatedBytesForCurrentThread() - alloc0);
  }
}
