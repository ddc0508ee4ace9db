using System;
using System.Globalization;
using GrCis.Cli.Animation;

namespace GrCis.Cli.ProgressViews;

/// <summary>The words of animation progress, shared by the plain and the live view.</summary>
public static class AnimationProgressText
{
  /// <summary><c>13/100 frames, 2.31 frames/s, 0:00:37 left</c>.</summary>
  public static string Of(AnimationProgress p)
  {
    string s = string.Create(CultureInfo.InvariantCulture, $"{p.FramesDone}/{p.FramesTotal} frames");
    if (p.FramesRendered > 0)
      s += string.Create(CultureInfo.InvariantCulture, $", {p.FramesPerSecond:0.00} frames/s");
    if (p.Remaining is TimeSpan left && p.FramesDone < p.FramesTotal)
      s += ", " + Duration(left) + " left";
    return s;
  }

  /// <summary><c>0:00:37</c>, or <c>2d 03:04:05</c> for very long runs.</summary>
  public static string Duration(TimeSpan t)
  {
    if (t < TimeSpan.Zero)
      t = TimeSpan.Zero;
    if (t.TotalDays >= 1)
      return string.Create(CultureInfo.InvariantCulture, $"{(int)t.TotalDays}d {t:hh\\:mm\\:ss}");
    return string.Create(CultureInfo.InvariantCulture, $"{(int)t.TotalHours}:{t:mm\\:ss}");
  }
}
