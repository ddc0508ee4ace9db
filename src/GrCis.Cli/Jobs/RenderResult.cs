using System;
using Rendering.Imaging;

namespace GrCis.Cli.Jobs;

/// <summary>A finished (or cancelled) render and its statistics.</summary>
public sealed record RenderResult(FloatImage Image, int SamplesPerPixel, TimeSpan Elapsed, long Rays, bool Cancelled)
{
  /// <summary>Rays per second, or null when the time is too short to say.</summary>
  public double? RaysPerSecond => Elapsed.TotalSeconds > 1e-3 && Rays > 0 ? Rays / Elapsed.TotalSeconds : null;
}
