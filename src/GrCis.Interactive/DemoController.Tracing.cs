using System;
using GrCis.Hosting;

namespace GrCis.Interactive;

public sealed partial class DemoController
{
  /// <summary>The pixel read-out for the last render.</summary>
  public ProbeResult Probe(int x, int y)
  {
    RenderJob job = LastJob ?? throw new InvalidOperationException("Render something first.");
    return PixelProbe.Probe(job, x, y, LastResult?.Job == job ? LastResult.Image : null);
  }

  /// <summary>The hit points of at most <paramref name="maxRays"/> primary rays of the last render, coloured by its image (<see cref="HitPointCloud"/>).</summary>
  public HitPointCloud HitPoints(int maxRays)
  {
    RenderJob job = LastJob ?? throw new InvalidOperationException("Render something first.");
    return HitPointCloud.Cast(job, maxRays, LastResult?.Job == job ? LastResult.Image : null);
  }
}
