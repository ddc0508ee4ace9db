using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Text.RegularExpressions;
using System.Threading;
using System.Threading.Tasks;
using GrCis.Hosting;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Interactive;

/// <summary>
/// Renders the frames of an animated scene with the frame renderer of <c>grcis animate</c>
/// (<see cref="FrameRenderer"/>: frame k at <see cref="AnimationTimeline.FrameTime"/>, the scene's time set before
/// the frame, the frame number mixed into the seeds), one frame at a time on all threads.
/// Optionally saves each frame (atomically) to a pattern like <c>out####.png</c>.
/// </summary>
public sealed partial class AnimationRun
{
  readonly FrameRenderer frames;
  IRayScene? workerScene;

  public AnimationRun(RenderJob job, AnimationTimeline timeline)
  {
    Job = job ?? throw new ArgumentNullException(nameof(job));
    Timeline = timeline ?? throw new ArgumentNullException(nameof(timeline));
    // The job's plan: the script's own function and renderer (copied per frame as grcis animate copies them), else the settings'.
    frames = new FrameRenderer(job.Scene, job.Plan, timeline);
  }

  public RenderJob Job { get; }

  public AnimationTimeline Timeline { get; }

  /// <summary>Raised after each frame (on the rendering thread).</summary>
  public event EventHandler<FrameRenderedEventArgs>? FrameRendered;

  /// <summary>The image of one frame (a still at the frame's time).</summary>
  public FloatImage RenderFrame(int frame, CancellationToken cancel = default)
  {
    workerScene ??= frames.CreateWorkerScene();
    return frames.Render(workerScene, frame, Job.Settings.EffectiveThreads, null, cancel);
  }

  /// <summary>Renders every frame in order; stops between frames when cancelled. Returns the frames rendered.</summary>
  public Task<int> RunAsync(string? outputPattern = null, CancellationToken cancel = default) =>
    Task.Factory.StartNew(() => Run(outputPattern, cancel), cancel, TaskCreationOptions.LongRunning, TaskScheduler.Default);

  int Run(string? pattern, CancellationToken cancel)
  {
    var clock = Stopwatch.StartNew();
    int total = Timeline.FrameCount, done = 0;
    for (int k = 0; k < total && !cancel.IsCancellationRequested; k++)
    {
      FloatImage image = RenderFrame(k, cancel);
      if (cancel.IsCancellationRequested)
        break; // a half-rendered frame is neither saved nor reported
      string? file = null;
      if (pattern != null)
      {
        file = FrameFileName(pattern, k);
        string? dir = Path.GetDirectoryName(Path.GetFullPath(file));
        if (dir != null)
          Directory.CreateDirectory(dir);
        PngFile.Save(file, RenderSetup.ToDisplayImage(image, Job.Renderer.Gamma));
      }
      done++;
      FrameRendered?.Invoke(this, new FrameRenderedEventArgs(k, Timeline.FrameTime(k), image, done, total, clock.Elapsed, file));
    }
    return done;
  }

  /// <summary>Replaces the last run of '#' with the zero-padded frame number (appends it when there is none).</summary>
  public static string FrameFileName(string pattern, int frame)
  {
    ArgumentException.ThrowIfNullOrEmpty(pattern);
    MatchCollection runs = Hashes().Matches(pattern);
    if (runs.Count == 0)
      return Path.ChangeExtension(pattern, null) + frame.ToString("D4", CultureInfo.InvariantCulture) + Path.GetExtension(pattern);
    Match m = runs[^1];
    return pattern[..m.Index] + frame.ToString("D" + m.Length, CultureInfo.InvariantCulture) + pattern[(m.Index + m.Length)..];
  }

  [GeneratedRegex("#+")]
  private static partial Regex Hashes();
}
