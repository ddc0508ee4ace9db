using System;
using Rendering.Execution;

namespace GrCis.Hosting;

/// <summary>A tile finished (of the tiles, or of a progressive render's pass: then <see cref="Fraction"/> counts the samples).</summary>
public sealed class RenderProgressEventArgs : EventArgs
{
  public RenderProgressEventArgs(RenderProgress progress, TimeSpan elapsed, double fraction)
  {
    Progress = progress;
    Elapsed = elapsed;
    Fraction = fraction;
  }

  public RenderProgress Progress { get; }

  public TimeSpan Elapsed { get; }

  /// <summary>Fraction of the render's work finished.</summary>
  public double Fraction { get; }
}
