using System;
using System.Collections.Generic;
using System.Globalization;
using GrCis.Cli.SceneSources;
using Rendering;

using GrCis.Hosting;

namespace GrCis.Cli.Animation;

/// <summary>
/// Which frames this process renders: the timeline (start, end, fps), the frame range of it
/// (<c>--frames</c>, default all) and this process's shard of that range (<c>--shard</c>).
/// </summary>
public sealed class AnimationPlan
{
  /// <summary>Used when neither the command line nor the scene gives a range.</summary>
  public const double DefaultStart = AnimationRange.DefaultStart, DefaultEnd = AnimationRange.DefaultEnd, DefaultFps = AnimationRange.DefaultFps;

  AnimationPlan(AnimationTimeline timeline, FrameRange range, ShardSpec shard, IReadOnlyList<int> frames)
  {
    Timeline = timeline;
    Range = range;
    Shard = shard;
    Frames = frames;
  }

  public AnimationTimeline Timeline { get; }

  /// <summary>The frames asked for (all shards together).</summary>
  public FrameRange Range { get; }

  public ShardSpec Shard { get; }

  /// <summary>This shard's frames of <see cref="Range"/>, ascending.</summary>
  public IReadOnlyList<int> Frames { get; }

  /// <summary>
  /// Start, end and fps each come from the command line, else the scene script's context
  /// (<paramref name="timing"/>), else the scene's own <see cref="ITimeDependent"/> range (start and
  /// end), else the defaults (0 to 10 s at 25 fps): <see cref="AnimationRange"/>.
  /// </summary>
  /// <exception cref="UsageException">An impossible range (end before start, fps not positive, frames outside the animation).</exception>
  public static AnimationPlan Create(double? from, double? to, double? fps, ISceneTiming? timing, IRayScene scene, FrameRange? frames, ShardSpec shard)
  {
    (double start, double end, double rate) = AnimationRange.Resolve(from, to, fps, timing, scene);

    AnimationTimeline timeline;
    try
    {
      timeline = new AnimationTimeline(start, end, rate);
    }
    catch (ArgumentOutOfRangeException e)
    {
      string what = e.ParamName == "fps" ? $"--fps {Num(rate)}" : $"--from {Num(start)} --to {Num(end)}";
      throw new UsageException($"invalid animation range {what}: {FirstSentence(e.Message)}");
    }

    FrameRange range = frames ?? new FrameRange(0, timeline.FrameCount - 1);
    if (range.Last >= timeline.FrameCount)
      throw new UsageException(
        $"invalid --frames {range}: the animation has frames 0-{timeline.FrameCount - 1} ({Num(start)} s to {Num(end)} s at {Num(rate)} fps)");

    var list = new List<int>();
    for (int k = range.First; k <= range.Last; k++)
      if (shard.Includes(k))
        list.Add(k);
    return new AnimationPlan(timeline, range, shard, list);
  }

  static string Num(double x) => x.ToString("0.###", CultureInfo.InvariantCulture);

  static string FirstSentence(string message)
  {
    int i = message.IndexOf(" (Parameter", StringComparison.Ordinal);
    return (i >= 0 ? message[..i] : message).Split('\n')[0].Trim();
  }
}
