using BenchmarkDotNet.Attributes;
using GrCis.Hosting;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Bench;

/// <summary>
/// What the kernel's generality costs on "Two spheres": the library's render of the built-in scene (the fast path:
/// prepared scene, Whitted kernel; one thread, 160×120, 16 jittered samples per pixel) against the same ray tree
/// written lean (<see cref="LeanWhittedProbe"/>). A ratio well above 1 for the kernel says its time goes to
/// bookkeeping (hit objects, material copies, dispatch, the query's general rules) rather than to the arithmetic
/// both must do (docs/performance.md, "What is left").
/// <c>dotnet run -c Release --project bench/GrCis.Bench -- --filter *LeanWhitted* --job short</c>
/// </summary>
public class LeanWhittedBenchmarks
{
  const int Width = 160, Height = 120, Grid = 4;
  IRayScene scene = null!;
  readonly LeanWhittedProbe probe = new();

  [GlobalSetup]
  public void Setup()
  {
    var sc = new DefaultRayScene();
    Scenes.TwoSpheres(sc, "");
    scene = sc;
  }

  /// <summary>The library's render of the built-in scene; returns the sum of its pixels.</summary>
  [Benchmark(Baseline = true)]
  public double Kernel() => Sum(RenderKernel(scene, Width, Height, Grid).Image);

  /// <summary>The lean ray tree; returns the sum of its pixels.</summary>
  [Benchmark]
  public double Lean()
  {
    double sum = 0.0;
    foreach (double v in probe.Render(Width, Height, Grid))
      sum += v;
    return sum;
  }

  /// <summary>
  /// Renders <paramref name="scene"/> on one thread with the library's Whitted ray tracer, through the hosting path every
  /// front end uses; its statistics count the rays.
  /// </summary>
  public static FrameResult RenderKernel(IRayScene scene, int width, int height, int grid)
  {
    var tracer = new RayTracing(scene);
    var synthesizer = new SupersamplingImageSynthesizer { Width = width, Height = height, Supersampling = grid * grid };
    return FrameRendering.Render(scene, tracer, synthesizer, new RenderOptions { Threads = 1 }, context: new RenderContext());
  }

  static double Sum(FloatImage image)
  {
    double sum = 0.0;
    foreach (float v in image.Data)
      sum += v;
    return sum;
  }
}
