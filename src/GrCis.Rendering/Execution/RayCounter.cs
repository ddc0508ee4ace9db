using System.Runtime.CompilerServices;

namespace Rendering.Execution;

/// <summary>
/// Per-worker ray counters: each worker increments its own count (no shared cache line per ray, no lost
/// updates; the count lives in its <see cref="WorkerContext"/>'s shading scratch, which the shading loop fetches
/// anyway); <see cref="TileRenderer"/> sums the workers' counts at the end of a render and adds them to GrCis's
/// <see cref="Intersection.countRays"/>, which scripts may read.
/// </summary>
public static class RayCounter
{
  /// <summary>Counts one primary or secondary ray (shadow rays included) on the calling thread.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static void CountRay() => ShadingScratch.Current.Rays++;

  /// <summary>Counts one ray that hit something (a blocked shadow ray included) on the calling thread.</summary>
  public static void CountHit() => ShadingScratch.Current.Hits++;

  /// <summary>Rays counted on the calling thread so far.</summary>
  public static long ThreadRays => ShadingScratch.Current.Rays;
}
