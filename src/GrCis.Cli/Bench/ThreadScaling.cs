using System;
using System.Threading;
using GrCis.Cli.Jobs;
using Rendering;
using Rendering.Accel;
using GrCis.Hosting;

namespace GrCis.Cli.Bench;

/// <summary>
/// <c>grcis bench --scaling</c>: a case's fast-path render on one thread and on N threads, alternated so
/// a change in the machine's load hits both, best of each. Scaling = t₁ / t_N (ideal: N).
/// </summary>
public static class ThreadScaling
{
  public static BenchResult Measure(BenchResult result, BenchCase c, IRayScene scene, int threads, int rounds, CancellationToken cancel)
  {
    double best1 = double.MaxValue, bestN = double.MaxValue;
    for (int r = 0; r < rounds && !cancel.IsCancellationRequested; r++)
    {
      best1 = Math.Min(best1, BenchSuite.Render(scene, c.Size, c.Spp, 1, AccelMode.Bvh, cancel, out _).Statistics.Elapsed.TotalSeconds);
      bestN = Math.Min(bestN, BenchSuite.Render(scene, c.Size, c.Spp, threads, AccelMode.Bvh, cancel, out _).Statistics.Elapsed.TotalSeconds);
    }
    if (cancel.IsCancellationRequested)
      return result;
    return result with { OneThreadSeconds = best1, ThreadsSeconds = bestN, Scaling = best1 / bestN };
  }
}
