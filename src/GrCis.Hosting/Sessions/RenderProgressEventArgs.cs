using System;
using Rendering.Execution;

namespace GrCis.Hosting;

/// <summary>A tile finished.</summary>
public sealed class RenderProgressEventArgs : EventArgs
{
  public RenderProgressEventArgs(RenderProgress progress, TimeSpan elapsed)
  {
    Progress = progress;
    Elapsed = elapsed;
  }

  public RenderProgress Progress { get; }

  public TimeSpan Elapsed { get; }

  public double Fraction => Progress.Fraction;
}
