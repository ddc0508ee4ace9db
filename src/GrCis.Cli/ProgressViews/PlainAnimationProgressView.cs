using System;
using System.IO;
using GrCis.Cli.Animation;

namespace GrCis.Cli.ProgressViews;

/// <summary>
/// Animation progress for logs and pipes (batch jobs): one line per saved frame, e.g.
/// <c>animate Orbit.cs: frame 12 saved, 13/100 frames, 2.31 frames/s, 0:00:37 left</c>.
/// </summary>
public sealed class PlainAnimationProgressView : IAnimationProgressView
{
  readonly TextWriter writer;

  public PlainAnimationProgressView(TextWriter writer) => this.writer = writer;

  public T Run<T>(string title, int framesTotal, int framesSkipped, Func<Action<AnimationProgress>, T> work)
  {
    string skipped = framesSkipped > 0 ? $" ({framesSkipped} already complete, skipped)" : "";
    writer.WriteLine($"{title}: {framesTotal} frames{skipped}");
    writer.Flush();
    return work(p =>
    {
      // Reports are serialized by the scheduler.
      writer.WriteLine($"{title}: frame {p.LastFrame} saved, {AnimationProgressText.Of(p)}");
      writer.Flush();
    });
  }
}
