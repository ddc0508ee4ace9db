using Rendering.Imaging;

namespace GrCis.Hosting;

/// <summary>A rendered frame (or part of one): the linear image, its statistics, and whether it was asked to stop (unfinished tiles are black).</summary>
public sealed record FrameResult(FloatImage Image, RenderStatistics Statistics, bool Cancelled)
{
  /// <summary>The per-pixel noise estimate, when the render took one.</summary>
  public Rendering.Execution.NoiseImage? Noise { get; init; }
}
