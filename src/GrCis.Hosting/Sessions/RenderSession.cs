using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Threading;
using System.Threading.Tasks;
using Rendering;
using Rendering.Accel;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Hosting;

/// <summary>
/// One render of a <see cref="RenderJob"/> as the demo shows it: a coarse preview first (every
/// <see cref="CoarseBlock"/>-th pixel filling its block), then the exact image tile by tile with a
/// preview at least every <see cref="PreviewInterval"/>, then <see cref="Completed"/>; or, when
/// <see cref="Progressive"/>, passes that add samples to every pixel. The final image is the one
/// <see cref="TileRenderer"/> produces for the job; <see cref="Stop"/> keeps finished tiles (or, progressive,
/// every pixel's mean so far).
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
  double fraction;   // of the work done, under the finished list's lock
  int passes;        // progressive passes begun

  public RenderSession(RenderJob job) => Job = job ?? throw new ArgumentNullException(nameof(job));

  public RenderJob Job { get; }

  /// <summary>Longest time between two previews while tiles are being rendered.</summary>
  public TimeSpan PreviewInterval { get; set; } = TimeSpan.FromMilliseconds(500);

  /// <summary>
  /// Render in passes over the whole image, each adding samples to every pixel (1, then n, 2n, … of n×n), like
  /// Cycles' viewport, instead of tile by tile; the final image is the same, bit for bit. Used when the job's
  /// renderer is the library's n×n supersampling with n ≥ 2 (not a subclass); otherwise the render goes by tiles.
  /// </summary>
  public bool Progressive { get; set; }

  // The preview interval in force: a non-positive one means the default.
  TimeSpan Cadence => PreviewInterval > TimeSpan.Zero ? PreviewInterval : TimeSpan.FromMilliseconds(500);

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
    var worker = new Thread(Run, Rendering.Execution.TileRenderer.WorkerStackSize) { IsBackground = true, Name = "grcis-session" };
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
    Publish(PreviewPass.Final, result.Image, force: true, noise: result.Statistics.Noise);
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
    var context = new RenderContext { Noise = new NoiseImage(job.Width, job.Height) };
    PreviewTicker? ticker = null;
    try
    {
      // Only the library's own n×n grid takes its samples in passes; a subclass (adaptive, a student's) renders its own way.
      if (Progressive && FrontEndRules.TakesSamplesInPasses(inner))
        image = RenderPasses(job, (SupersamplingImageSynthesizer)inner, options, context, clock, token);
      else
        image = RenderTiles(job, options, context, clock, token, out ticker);
    }
    catch (Exception ex) when (ex is RenderException or AggregateException)
    {
      error = ex is AggregateException agg ? agg.Flatten().InnerExceptions[0] : ex;
      // A script's or module's class threw: say where, as grcis render does.
      error = job.LocateError?.Invoke(error.InnerException ?? error) ?? error;
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
    bool complete = image != null && !token.IsCancellationRequested;
    // Stopped or failed: a progressive render keeps every pixel's mean so far, a tiled one its finished tiles.
    if (!complete)
      image = passes > 0 ? live : KeepTiles(live, tiles);
    RenderStatistics stats = RenderStatistics.Of(inner, options, context, clock.Elapsed, complete ? tilesTotal : tiles.Length, tilesTotal, image!);
    return new RenderResult(job, new FrameResult(image!, stats, !complete && error == null) { Noise = context.Noise }, tiles, error);
  }

  /// <summary>Coarse pass, then the tiles; the coarse pass's pixels are exact and not rendered again.</summary>
  FloatImage RenderTiles(RenderJob job, RenderOptions options, RenderContext context, Stopwatch clock, CancellationToken token, out PreviewTicker ticker)
  {
    bool[]? coarse = null;
    if (CoarseBlock > 1)
    {
      coarse = CoarsePass(job, options, live!, CoarseBlock, context, token);
      if (!token.IsCancellationRequested)
        Publish(PreviewPass.Coarse, live, force: false);
    }

    ticker = new PreviewTicker(Cadence, () => Publish(PreviewPass.Tiles, live, force: false));

    var synth = new PreviewSynthesizer(job.Renderer, live!, coarse, CoarseBlock);
    return TileRenderer.Render(job.Scene, job.ImageFunction, synth, options, p => TileDone(p, clock, 0.0, 1.0), token, context);
  }

  /// <summary>
  /// A tile finished: recorded, and reported with the fraction of the render done, for a pass that began at
  /// <paramref name="before"/> of the work and is <paramref name="share"/> of it (the tile mode: one pass, 0 and 1).
  /// </summary>
  void TileDone(RenderProgress p, Stopwatch clock, double before, double share)
  {
    double done;
    lock (finished)
    {
      finished.Add(p.LastTile);
      fraction = done = before + share * finished.Count / Math.Max(1, TileCount());
    }
    Raise(ProgressChanged, new RenderProgressEventArgs(p, clock.Elapsed, done));
  }

  /// <summary>
  /// Progressive rendering: passes over the whole image, each taking the next samples of every pixel
  /// (<see cref="SamplePassSynthesizer.PassEnds"/>), with a preview after each pass and while it runs.
  /// </summary>
  FloatImage? RenderPasses(RenderJob job, SupersamplingImageSynthesizer grid, RenderOptions options, RenderContext context,
    Stopwatch clock, CancellationToken token)
  {
    var synth = new SamplePassSynthesizer(grid, live!, context.Noise!);
    int[] ends = SamplePassSynthesizer.PassEnds(grid.SuperXY);
    int total = grid.SuperXY * grid.SuperXY;
    FloatImage? image = null;
    using var ticker = new PreviewTicker(Cadence, () => Publish(PreviewPass.Samples, live, force: false));
    for (int k = 0; k < ends.Length && !token.IsCancellationRequested; k++)
    {
      synth.First = k == 0 ? 0 : ends[k - 1];
      synth.End = ends[k];
      double before = (double)synth.First / total, share = (double)(synth.End - synth.First) / total;
      lock (finished)
        finished.Clear();
      passes = k + 1;
      image = TileRenderer.Render(job.Scene, job.ImageFunction, synth, options, p => TileDone(p, clock, before, share), token, context);
      if (!token.IsCancellationRequested && k < ends.Length - 1)
        Publish(PreviewPass.Samples, live, force: false, synth.End, context.Noise!.Rmse());
    }
    return token.IsCancellationRequested ? null : image;
  }

  /// <summary>
  /// Renders one pixel per block (its exact final value) and fills the block with it; returns which blocks
  /// are done, so the tile pass takes those pixels from here instead of rendering them again.
  /// </summary>
  /// <param name="context">The render's context: the pass's rays count toward the render, as its pixels are the render's.</param>
  static bool[] CoarsePass(RenderJob job, RenderOptions options, FloatImage target, int block, RenderContext context, CancellationToken token)
  {
    int w = job.Width, h = job.Height;
    int rows = (h + block - 1) / block, columns = (w + block - 1) / block;
    var done = new bool[rows * columns];
    ImageSynthesizer renderer = job.Renderer;
    var po = new ParallelOptions { MaxDegreeOfParallelism = Math.Max(1, options.EffectiveThreads) };
    WorkerContext caller = WorkerContext.Current;
    Parallel.For(0, rows, po,
      // Each task is a worker of the render (a script's code stuck in a loop stops with the session, see Interruption).
      () => (Color: new double[target.Bands], Scope: WorkerContext.Begin(context, job.Scene, job.ImageFunction, renderer, options, token, parent: caller)),
      (row, _, state) =>
      {
        double[] color = state.Color;
        if (token.IsCancellationRequested)
          return state;
        int y0 = row * block, y1 = Math.Min(y0 + block, h);
        try
        {
          for (int x0 = 0; x0 < w; x0 += block)
          {
            renderer.PixelLinear(x0, y0, color);
            int x1 = Math.Min(x0 + block, w);
            for (int y = y0; y < y1; y++)
              for (int x = x0; x < x1; x++)
                target.SetPixel(x, y, color);
            done[row * columns + x0 / block] = true;
          }
        }
        catch (OperationCanceledException) when (token.IsCancellationRequested)
        {
        }
        return state;
      },
      state => state.Scope.Dispose());
    return done;
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

  void Publish(PreviewPass pass, FloatImage? source, bool force, int? samples = null, double? noise = null)
  {
    if (source == null)
      return;
    lock (publishLock)
    {
      // A late tick must not follow the final image.
      if (tilesOver && !force)
        return;
      var snapshot = new FloatImage(source.Width, source.Height, source.Bands, (float[])source.Data.Clone());
      double shown;
      lock (finished)
        shown = pass == PreviewPass.Final ? 1.0 : fraction;
      Raise(PreviewReady, new RenderPreviewEventArgs(snapshot, pass, shown, sequence++, Job.Renderer.Gamma) { Samples = samples, Noise = noise });
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
