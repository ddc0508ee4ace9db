using System;

namespace Rendering;

/// <summary>
/// The frames of an animation: frame k is at <c>Start + k / Fps</c>, computed (never accumulated),
/// and both ends are included as in GrCis: the last frame is the last one not later than
/// <c>End</c> plus half a frame, so <c>FrameCount = floor((End − Start) · Fps + ½) + 1</c>.
/// </summary>
public sealed class AnimationTimeline
{
  /// <summary>The frames from <paramref name="start"/> to <paramref name="end"/> at <paramref name="fps"/> frames per second.</summary>
  /// <param name="start">Time of the first frame in seconds.</param>
  /// <param name="end">End of the animation in seconds, not before <paramref name="start"/>.</param>
  /// <param name="fps">Frames per second, positive.</param>
  /// <exception cref="ArgumentOutOfRangeException">A time is not finite, the end comes before the start, the rate is not positive, or the frames would be too many.</exception>
  public AnimationTimeline(double start, double end, double fps)
  {
    if (!double.IsFinite(start) || !double.IsFinite(end))
      throw new ArgumentOutOfRangeException(nameof(end), $"Animation times must be finite numbers, got {start} to {end}.");
    if (end < start)
      throw new ArgumentOutOfRangeException(nameof(end), end, $"The animation ends ({end}) before it starts ({start}).");
    if (!(fps > 0.0) || !double.IsFinite(fps))
      throw new ArgumentOutOfRangeException(nameof(fps), fps, "Frames per second must be a positive number.");
    double frames = Math.Floor((end - start) * fps + 0.5) + 1.0;
    if (frames > int.MaxValue)
      throw new ArgumentOutOfRangeException(nameof(fps), fps, $"{frames} frames are too many.");
    Start = start;
    End = end;
    Fps = fps;
    FrameCount = (int)frames;
  }

  /// <summary>Time of the first frame in seconds.</summary>
  public double Start { get; }

  /// <summary>End of the animation in seconds (the last frame lies at most half a frame after it).</summary>
  public double End { get; }

  /// <summary>Frames per second.</summary>
  public double Fps { get; }

  /// <summary>Number of frames, both ends included (see <see cref="AnimationTimeline"/>).</summary>
  public int FrameCount { get; }

  /// <summary>Time of frame <paramref name="k"/> (0-based).</summary>
  public double FrameTime(int k)
  {
    if (k < 0 || k >= FrameCount)
      throw new ArgumentOutOfRangeException(nameof(k), k, $"Frame numbers run from 0 to {FrameCount - 1}.");
    return Start + k / Fps;
  }

  /// <summary>Length of one frame in seconds.</summary>
  public double FrameDuration => 1.0 / Fps;
}
