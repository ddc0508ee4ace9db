using System.Threading;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Interactive;

/// <summary>Counts rays and hits for the statistics line; per-thread counters, summed at the end.</summary>
internal sealed class CountingObserver : RayObserver
{
  sealed class Counters
  {
    public long Rays, Hits;
  }

  readonly ThreadLocal<Counters> counters = new(() => new Counters(), trackAllValues: true);

  public override void EndRay(RayKind kind, int depth, in Vector3d origin, in Vector3d direction, Intersection? hit)
  {
    Counters c = counters.Value!;
    c.Rays++;
    if (hit != null)
      c.Hits++;
  }

  public override void ShadowRay(in Vector3d origin, in Vector3d direction, bool blocked)
  {
    Counters c = counters.Value!;
    c.Rays++;
    if (blocked)
      c.Hits++;
  }

  /// <summary>Totals; call after the render threads have finished.</summary>
  public (long Rays, long Hits) Totals()
  {
    long rays = 0, hits = 0;
    foreach (Counters c in counters.Values)
    {
      rays += c.Rays;
      hits += c.Hits;
    }
    return (rays, hits);
  }
}
