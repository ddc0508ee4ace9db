using System;
using Rendering.Execution;

namespace GrCis.Hosting;

/// <summary>A tile finished (of a progressive render's pass: <see cref="Fraction"/> counts the samples).</summary>
public sealed class RenderProgressEventArgs : EventArgs
{
  public RenderProgressEventArgs(RenderProgress progress, TimeSpan elapsed, double? fraction = null)
  {
    Progress = progress;
    Elapsed = elapsed;
    Fraction = fraction ?? progress.Fraction;
  }

  public RenderProgress Progress { get; }

  public TimeSpan Elapsed { get; }

  /// <summary>Fraction of the render's work finished.</summary>
  public double Fraction { get; }
}
