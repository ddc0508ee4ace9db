using System;

namespace GrCis.Cli.Animation;

/// <summary>
/// Where an animation run stands: frames done of this run's frames (frames skipped by
/// <c>--resume</c> count as done), the rate of frames rendered so far and the time left at that rate.
/// </summary>
public readonly record struct AnimationProgress(int FramesDone, int FramesTotal, int FramesRendered, TimeSpan Elapsed, int LastFrame)
{
  /// <summary>Frames rendered per second of wall time (0 until one is done).</summary>
  public double FramesPerSecond => FramesRendered > 0 && Elapsed.TotalSeconds > 0 ? FramesRendered / Elapsed.TotalSeconds : 0.0;

  /// <summary>Estimated time to the last frame, or null before the first frame gives a rate.</summary>
  public TimeSpan? Remaining => FramesPerSecond > 0 ? TimeSpan.FromSeconds((FramesTotal - FramesDone) / FramesPerSecond) : null;

  public double Fraction => FramesTotal == 0 ? 1.0 : (double)FramesDone / FramesTotal;
}
