using System;
using System.Collections.Generic;
using System.Threading;
using System.Threading.Tasks;
using GrCis.Interactive;
using Rendering.Imaging;

namespace GrCis.Studio;

/// <summary>
/// One animation run of the studio: the frames of a time range rendered in order (as the demo's
/// <see cref="AnimationRun"/> does), with progress and ETA. With a folder the frames are written there as
/// <c>out####.png</c> and the page scrubs through those files (encoded once, nothing held in memory); without
/// one each frame's PNG is kept in memory.
/// </summary>
public sealed class StudioAnimation
{
  readonly object sync = new();
  // Per finished frame: its PNG bytes (no folder) or the file it was saved to.
  readonly List<(byte[]? Png, string? File)> frames = new();
  readonly CancellationTokenSource cancel = new();
  int total;
  TimeSpan elapsed, eta;
  string? error;
  bool running = true;

  StudioAnimation(string? folder, double fps, AnimationRun? run = null)
  {
    Folder = folder;
    Fps = fps;
    Run = run;
  }

  /// <summary>The run (its job's scene and its timeline), for the scene of a frame as glTF (<see cref="StudioSceneFiles"/>).</summary>
  internal AnimationRun? Run { get; }

  /// <summary>Where the frames are written, or null (kept in memory only).</summary>
  public string? Folder { get; }

  /// <summary>The run's frames per second: the rate the page plays the finished frames at.</summary>
  public double Fps { get; }

  /// <summary>Starts rendering <paramref name="run"/>'s frames on a worker thread.</summary>
  /// <param name="changed">Called after each frame and at the end of the run (the page is told of them).</param>
  public static StudioAnimation Start(AnimationRun run, string? folder, Action? changed = null)
  {
    var animation = new StudioAnimation(folder, run.Timeline.Fps, run) { total = run.Timeline.FrameCount };
    run.FrameRendered += (_, e) =>
    {
      byte[]? png = e.File != null ? null : PngEncoder.Default.Encode(Rendering.Execution.RenderSetup.ToDisplayImage(e.Image, run.Job.Renderer.Gamma));
      lock (animation.sync)
      {
        animation.frames.Add((png, e.File));
        animation.elapsed = e.Elapsed;
        animation.eta = e.Eta;
      }
      changed?.Invoke();
    };
    string? pattern = folder == null ? null : System.IO.Path.Combine(folder, "out####.png");
    run.RunAsync(pattern, animation.cancel.Token).ContinueWith(t =>
    {
      lock (animation.sync)
      {
        animation.running = false;
        if (t.Exception != null)
          animation.error = t.Exception.GetBaseException().Message;
      }
      changed?.Invoke();
    }, TaskScheduler.Default);
    return animation;
  }

  public void Stop() => cancel.Cancel();

  /// <summary>True until the last frame is done, the run stopped, or a frame failed.</summary>
  public bool Running
  {
    get
    {
      lock (sync)
        return running;
    }
  }

  /// <summary>The finished frame <paramref name="k"/> as PNG, or null when it is not (yet) rendered or its file is gone.</summary>
  public byte[]? Frame(int k)
  {
    (byte[]? Png, string? File) frame;
    lock (sync)
    {
      if (k < 0 || k >= frames.Count)
        return null;
      frame = frames[k];
    }
    if (frame.Png != null)
      return frame.Png;
    try
    {
      return System.IO.File.ReadAllBytes(frame.File!);
    }
    catch (Exception e) when (e is System.IO.IOException or UnauthorizedAccessException)
    {
      return null;   // deleted or replaced by the user since: the page shows the frame as missing
    }
  }

  /// <summary>What the page shows of the run.</summary>
  public AnimationStatus Status()
  {
    lock (sync)
      return new AnimationStatus(running, frames.Count, total, elapsed.TotalSeconds, eta.TotalSeconds, error, Folder, Fps);
  }
}
