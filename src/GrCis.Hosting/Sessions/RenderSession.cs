using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Threading;
using System.Threading.Tasks;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Hosting;

/// <summary>
/// One render of a <see cref="RenderJob"/> as the demo shows it: a coarse preview first (every
/// <see cref="CoarseBlock"/>-th pixel filling its block), then the exact image tile by tile with a
/// preview at least every <see cref="PreviewInterval"/>, then <see cref="Completed"/>. The final image
/// is the one <see cref="TileRenderer"/> produces for the job; <see cref="Stop"/> keeps finished tiles.
/// Events come from a worker thread unless <see cref="EventContext"/> is set (e.g. the UI's context).
/// </summary>
public sealed class RenderSession : IDisposable
{
  readonly CancellationTokenSource cancel = new();
  readonly TaskCompletionSource<RenderResult> done = new(TaskCreationOptions.RunContinuationsAsynchronously);
  readonly object publishLock = new();
  readonly List<Tile> finished = new();
  FloatImage? live;
  int sequence;
  int started;
  bool tilesOver;

  public RenderSession(RenderJob job) => Job = job ?? throw new ArgumentNullException(nameof(job));

  public RenderJob Job { get; }

  /// <summary>Longest time between two previews while tiles are being rendered.</summary>
  public TimeSpan PreviewInterval { get; set; } = TimeSpan.FromMilliseconds(500);

  /// <summary>Block size of the coarse first pass; 1 or less skips it.</summary>
  public int CoarseBlock { get; set; } = 8;

  /// <summary>Where events are raised; null = on the render's worker thread.</summary>
  public SynchronizationContext? EventContext { get; set; }

  public event EventHandler<RenderPreviewEventArgs>? PreviewReady;

  public event EventHandler<RenderProgressEventArgs>? ProgressChanged;

  public event EventHandler<RenderCompletedEventArgs>? Completed;

  public bool IsRunning => Volatile.Read(ref started) == 1 && !done.Task.IsCompleted;

  /// <summary>The result once the render ended.</summary>
  public RenderResult? Result => done.Task.IsCompletedSuccessfully ? done.Task.Result : null;

  /// <summary>Completes with the result (also when stopped or failed; see <see cref="RenderResult.Error"/>).</summary>
  public Task<RenderResult> Task => done.Task;

  /// <summary>Starts rendering on a background thread; returns <see cref="Task"/>.</summary>
  public Task<RenderResult> Start()
  {
    if (Interlocked.Exchange(ref started, 1) != 0)
      throw new InvalidOperationException("A render session runs once; create a new one to render again.");
    var worker = new Thread(Run) { IsBackground = true, Name = "grcis-session" };
    worker.Start();
    return done.Task;
  }

  /// <summary>Asks the render to stop after the tiles in progress; finished tiles are kept.</summary>
  public void Stop() => cancel.Cancel();

  public void Dispose()
  {
    Stop();
    if (Volatile.Read(ref started) == 1)
      done.Task.Wait();
    cancel.Dispose();
  }

  void Run()
  {
    RenderResult result;
    try
    {
      result = Render();
    }
    catch (Exception ex)
    {
      // Not expected (Render catches scene failures); still, never leave the caller waiting.
      done.TrySetException(ex);
      return;
    }
    Publish(PreviewPass.Final, result.Image, force: true);
    Raise(Completed, new RenderCompletedEventArgs(result));
    done.TrySetResult(result);
  }

  RenderResult Render()
  {
    RenderJob job = Job;
    RenderOptions options = job.Options;
    CancellationToken token = cancel.Token;
    var clock = Stopwatch.StartNew();
    live = new FloatImage(job.Width, job.Height);
    int tilesTotal = TileCount();

    ImageSynthesizer inner = job.Renderer;
    FloatImage? image = null;
    Exception? error = null;
    var context = new RenderContext();
    PreviewTicker? ticker = null;
    try
    {
      if (CoarseBlock > 1)
      {
        CoarsePass(job, options, live, CoarseBlock, new RenderContext { Queries = context.Queries }, token);
        if (!token.IsCancellationRequested)
          Publish(PreviewPass.Coarse, live, force: false);
      }

      TimeSpan interval = PreviewInterval > TimeSpan.Zero ? PreviewInterval : TimeSpan.FromMilliseconds(500);
      ticker = new PreviewTicker(interval, () => Publish(PreviewPass.Tiles, live, force: false));

      var synth = new PreviewSynthesizer(inner, live);
      image = TileRenderer.Render(job.Scene, job.ImageFunction, synth, options, p =>
      {
        lock (finished)
          finished.Add(p.LastTile);
        Raise(ProgressChanged, new RenderProgressEventArgs(p, clock.Elapsed));
      }, token, context);
    }
    catch (Exception ex) when (ex is RenderException or AggregateException)
    {
      error = ex is AggregateException agg ? agg.Flatten().InnerExceptions[0] : ex;
    }
    finally
    {
      ticker?.Dispose();
      lock (publishLock)
        tilesOver = true;
    }
    clock.Stop();

    Tile[] tiles;
    lock (finished)
      tiles = finished.ToArray();
    image ??= KeepTiles(live, tiles);

    RenderStatistics stats = RenderStatistics.Of(inner, options, context, clock.Elapsed, tiles.Length, tilesTotal);
    bool cancelled = token.IsCancellationRequested && tiles.Length < tilesTotal;
    return new RenderResult(job, new FrameResult(image, stats, cancelled), tiles, error);
  }

  /// <summary>Renders one pixel per block (its exact final value) and fills the block with it.</summary>
  /// <param name="preview">The pass's own counts, sharing the render's prepared scenes.</param>
  static void CoarsePass(RenderJob job, RenderOptions options, FloatImage target, int block, RenderContext preview, CancellationToken token)
  {
    int w = job.Width, h = job.Height;
    int rows = (h + block - 1) / block;
    ImageSynthesizer renderer = job.Renderer;
    var po = new ParallelOptions { MaxDegreeOfParallelism = Math.Max(1, options.EffectiveThreads) };
    Parallel.For(0, rows, po,
      () =>
      {
        MT.InitThreadData();
        MT.SetRendering(SceneCloner.CloneForWorker(job.Scene), job.ImageFunction, renderer);
        MT.seed = options.Seed;
        MT.frame = options.Frame;
        return (Color: new double[target.Bands], Scope: preview.Enter());
      },
      (row, _, state) =>
      {
        double[] color = state.Color;
        if (token.IsCancellationRequested)
          return state;
        // A script's code stuck in a loop stops with the session (see Interruption).
        using Interruption.Scope interruption = Interruption.Use(token);
        int y0 = row * block, y1 = Math.Min(y0 + block, h);
        try
        {
          for (int x0 = 0; x0 < w; x0 += block)
          {
            renderer.RenderPixelLinear(x0, y0, color);
            int x1 = Math.Min(x0 + block, w);
            for (int y = y0; y < y1; y++)
              for (int x = x0; x < x1; x++)
                target.SetPixel(x, y, color);
          }
        }
        catch (OperationCanceledException) when (token.IsCancellationRequested)
        {
        }
        return state;
      },
      state =>
      {
        state.Scope.Dispose();
        MT.SetRendering(null, null, null);
      });
  }

  /// <summary>An image with only the given tiles copied from <paramref name="source"/> (used after a failure).</summary>
  static FloatImage KeepTiles(FloatImage source, Tile[] tiles)
  {
    var image = new FloatImage(source.Width, source.Height, source.Bands);
    foreach (Tile t in tiles)
      for (int y = t.Y1; y < t.Y2; y++)
      {
        int from = source.PixelIndex(t.X1, y), count = (t.X2 - t.X1) * source.Bands;
        Array.Copy(source.Data, from, image.Data, from, count);
      }
    return image;
  }

  void Publish(PreviewPass pass, FloatImage? source, bool force)
  {
    if (source == null)
      return;
    lock (publishLock)
    {
      // A late tick must not follow the final image.
      if (tilesOver && !force)
        return;
      var snapshot = new FloatImage(source.Width, source.Height, source.Bands, (float[])source.Data.Clone());
      double fraction;
      lock (finished)
        fraction = pass == PreviewPass.Final ? 1.0 : (double)finished.Count / Math.Max(1, TileCount());
      Raise(PreviewReady, new RenderPreviewEventArgs(snapshot, pass, fraction, sequence++, Job.Renderer.Gamma));
    }
  }

  int tileCount = -1;

  int TileCount()
  {
    if (tileCount < 0)
      tileCount = TileRenderer.MakeTiles(Job.Width, Job.Height, Job.Options.TileSize).Count;
    return tileCount;
  }

  void Raise<T>(EventHandler<T>? handler, T args) => EventContext.Raise(handler, this, args);
}
