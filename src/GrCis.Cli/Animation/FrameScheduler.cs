using System;
using System.Collections.Generic;
using System.Threading;
using GrCis.Cli.Jobs;
using GrCis.Hosting;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Cli.Animation;

/// <summary>
/// Renders a list of frames on the cores, in one of two ways: several frames at once, each on one
/// thread (<see cref="ParallelMode.Frames"/>; the last frames, fewer than the threads, go one at a
/// time on all threads), or one frame at a time with its tiles on every thread
/// (<see cref="ParallelMode.Tiles"/>). Each finished frame is saved at once (atomically), so an
/// interrupted run keeps every frame it finished. Both ways give the same bytes: a pixel's
/// randomness comes from (seed, frame, pixel), never from the thread that rendered it.
/// </summary>
public sealed class FrameScheduler
{
  /// <summary>
  /// Frames up to this many pixels render frames-in-parallel under <see cref="ParallelMode.Auto"/>;
  /// larger ones tiles-in-parallel. Measured on 2 cores (docs/animation.md): from 80x60 to 640x480
  /// frames in parallel was as fast or faster (tiles in parallel idles a core while a frame is
  /// prepared, encoded and flushed to disk, and while its last tiles finish); above that the gain
  /// shrinks with the frame, and one frame at a time keeps memory and the time to each frame low.
  /// </summary>
  public const long FramesInParallelMaxPixels = 640 * 480;

  readonly FrameRenderer renderer;
  readonly FrameStore store;
  readonly object sync = new();

  public FrameScheduler(FrameRenderer renderer, FrameStore store)
  {
    this.renderer = renderer;
    this.store = store;
  }

  /// <summary>Resolves <see cref="ParallelMode.Auto"/>: frames in parallel for small frames when there are several threads and frames.</summary>
  public static ParallelMode Choose(ParallelMode requested, ImageSize size, int threads, int frames)
  {
    if (requested != ParallelMode.Auto)
      return requested;
    if (threads < 2 || frames < 2)
      return ParallelMode.Tiles;
    return (long)size.Width * size.Height <= FramesInParallelMaxPixels ? ParallelMode.Frames : ParallelMode.Tiles;
  }

  /// <summary>
  /// Renders and saves <paramref name="frames"/> in the given mode (not <see cref="ParallelMode.Auto"/>)
  /// on <paramref name="threads"/> threads. Stops between frames when cancelled (a frame cut short is
  /// not saved) and at the first failure, which it rethrows. Returns how many frames it saved.
  /// </summary>
  /// <param name="frameSaved">Called (serialized) after each saved frame with the frame number.</param>
  public int Run(IReadOnlyList<int> frames, ParallelMode mode, int threads, Action<int> frameSaved, CancellationToken cancel)
  {
    ArgumentNullException.ThrowIfNull(frames);
    ArgumentNullException.ThrowIfNull(frameSaved);
    if (mode == ParallelMode.Auto)
      throw new ArgumentException("Resolve Auto with Choose first.", nameof(mode));
    if (frames.Count == 0)
      return 0;
    threads = Math.Max(1, threads);
    if (mode == ParallelMode.Tiles || threads == 1 || frames.Count < threads)
      return RunTilesInParallel(frames, threads, frameSaved, cancel);

    // Frames in parallel, except the last few that cannot keep every thread busy: those go one at a
    // time on all threads, so no core idles at the end.
    int bulk = frames.Count - frames.Count % threads;
    int saved = RunFramesInParallel(Slice(frames, 0, bulk), threads, frameSaved, cancel);
    if (bulk < frames.Count && !cancel.IsCancellationRequested)
      saved += RunTilesInParallel(Slice(frames, bulk, frames.Count - bulk), threads, frameSaved, cancel);
    return saved;
  }

  static List<int> Slice(IReadOnlyList<int> frames, int start, int count)
  {
    var list = new List<int>(count);
    for (int i = start; i < start + count; i++)
      list.Add(frames[i]);
    return list;
  }

  int RunTilesInParallel(IReadOnlyList<int> frames, int threads, Action<int> frameSaved, CancellationToken cancel)
  {
    IRayScene scene = renderer.CreateWorkerScene();
    int saved = 0;
    foreach (int k in frames)
    {
      if (cancel.IsCancellationRequested)
        break;
      FloatImage image = renderer.Render(scene, k, threads, null, cancel);
      if (cancel.IsCancellationRequested)
        break;
      store.Save(k, image);
      saved++;
      frameSaved(k);
    }
    return saved;
  }

  int RunFramesInParallel(IReadOnlyList<int> frames, int workers, Action<int> frameSaved, CancellationToken cancel)
  {
    // Clone on this thread: each worker owns the moving parts of its scene for all its frames.
    var scenes = new IRayScene[workers];
    for (int i = 0; i < workers; i++)
      scenes[i] = renderer.CreateWorkerScene();

    int next = -1, saved = 0;
    var failure = new EarliestFailure();

    void Work(IRayScene scene)
    {
      int i = -1;
      try
      {
        while (!cancel.IsCancellationRequested && failure.Exception == null &&
               (i = Interlocked.Increment(ref next)) < frames.Count)
        {
          int k = frames[i];
          FloatImage image = renderer.Render(scene, k, 1, null, cancel);
          // A frame cut short by Ctrl+C is incomplete; one finished while another worker failed is kept.
          if (cancel.IsCancellationRequested)
            break;
          store.Save(k, image);
          lock (sync)
          {
            saved++;
            frameSaved(k);
          }
        }
      }
      catch (Exception e)
      {
        // Several frames in flight may fail; report the earliest, as one thread would.
        failure.Report(i, e);
      }
    }

    var threads = new Thread[workers];
    for (int i = 0; i < workers; i++)
    {
      IRayScene scene = scenes[i];
      threads[i] = new Thread(() => Work(scene), Rendering.Execution.TileRenderer.WorkerStackSize) { IsBackground = true, Name = $"grcis-frame-{i}" };
      threads[i].Start();
    }
    foreach (Thread t in threads)
      t.Join();

    if (failure.Exception is Exception e)
      System.Runtime.ExceptionServices.ExceptionDispatchInfo.Capture(e).Throw();
    return saved;
  }
}
