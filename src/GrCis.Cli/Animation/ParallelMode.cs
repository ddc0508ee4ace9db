namespace GrCis.Cli.Animation;

/// <summary><c>--parallel</c>: how an animation uses the cores.</summary>
public enum ParallelMode
{
  /// <summary>Choose by frame size (see <see cref="FrameScheduler.Choose"/>).</summary>
  Auto,

  /// <summary>Several frames at once, each on one thread.</summary>
  Frames,

  /// <summary>One frame at a time, its tiles on all threads.</summary>
  Tiles,
}
