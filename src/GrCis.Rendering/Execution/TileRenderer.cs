using System;
using System.Collections.Generic;
using System.Threading;
using Rendering.Imaging;

namespace Rendering.Execution;

/// <summary>
/// Renders an image in tiles on worker threads, each in a <see cref="WorkerContext"/> of its own. Every pixel's
/// randomness is derived from (seed, frame, pixel) in <see cref="MT.StartPixel"/> and the worker's <see cref="Sampler"/>,
/// so the image is bit-identical for any number of threads and any tile order. Cancellation keeps every tile finished so far.
/// </summary>
public static class TileRenderer
{
  /// <summary>
  /// The stack of every thread that runs user code while rendering (16 MiB, reserved, not committed): the same on every
  /// platform (.NET's default is 1.5 MiB on Windows), and room for <see cref="Recursion.MaxDepth"/> calls of big frames.
  /// </summary>
  public const int WorkerStackSize = 16 << 20;

  /// <summary>Tiles of an image in row-major order.</summary>
  public static List<Tile> MakeTiles(int width, int height, int tileSize)
  {
    if (tileSize < 1)
      throw new ArgumentOutOfRangeException(nameof(tileSize), tileSize, "Tile size must be positive.");
    var tiles = new List<Tile>();
    for (int y = 0; y < height; y += tileSize)
      for (int x = 0; x < width; x += tileSize)
        tiles.Add(new Tile(x, y, Math.Min(x + tileSize, width), Math.Min(y + tileSize, height)));
    return tiles;
  }

  /// <summary>
  /// Renders <paramref name="scene"/> through <paramref name="renderer"/> into a new linear image.
  /// Returns the image even when cancelled (unfinished tiles stay black); check the token to know.
  /// </summary>
  /// <param name="context">The render's observer and ray counts (read <see cref="RenderContext.Rays"/> afterwards); null = a private one.</param>
  public static FloatImage Render(
    IRayScene scene,
    IImageFunction imageFunction,
    ImageSynthesizer renderer,
    RenderOptions options,
    Action<RenderProgress>? progress = null,
    CancellationToken cancel = default,
    RenderContext? context = null)
  {
    ArgumentNullException.ThrowIfNull(scene);
    ArgumentNullException.ThrowIfNull(imageFunction);
    ArgumentNullException.ThrowIfNull(renderer);
    ArgumentNullException.ThrowIfNull(options);

    int width = renderer.Width, height = renderer.Height;
    var image = new FloatImage(width, height);
    renderer.ImageFunction = imageFunction;

    // Size the function on this thread; one built without a scene reaches it through MT.scene.
    // Workers clone the scene afterwards, so their clones inherit the camera size.
    IRayScene? callerScene = MT.scene;
    MT.scene = scene;
    try
    {
      imageFunction.Width = width;
      imageFunction.Height = height;
    }
    finally
    {
      MT.scene = callerScene;
    }

    // Prepare the fast path once per frame, into this render's queries, before the workers share it read-only.
    context ??= new RenderContext();
    if (imageFunction is RayCasting rc)
      using (context.Enter())
        rc.Prepare(scene);
    // The one place a frame's fast path is chosen: the function's prepared kernel, if it has one.
    renderer.Kernel = Accel.WhittedKernel.For(imageFunction);

    IReadOnlyList<Tile> tiles = options.Tiles ?? MakeTiles(width, height, options.TileSize);
    int next = -1, done = 0;
    int threads = Math.Clamp(options.EffectiveThreads, 1, Math.Max(1, tiles.Count));
    var failure = new EarliestFailure();
    object progressLock = new();
    long raysBefore = context.Rays, hitsBefore = context.Hits;

    int nextWorker = -1;
    MT.threads = threads;
    WorkerContext caller = WorkerContext.Current;

    void Work()
    {
      int k = -1;
      try
      {
        // The worker's context: its scene, sampler, scratch and counts; a script's texture or shader stuck in a loop
        // stops with the render (cancel).
        using WorkerContext.Scope worker = WorkerContext.Begin(context, scene, imageFunction, renderer, options, cancel,
                                                               Interlocked.Increment(ref nextWorker), caller);
        while (!cancel.IsCancellationRequested && failure.Exception == null &&
               (k = Interlocked.Increment(ref next)) < tiles.Count)
        {
          Tile t = tiles[k];
          renderer.RenderRectangle(image, t.X1, t.Y1, t.X2, t.Y2);
          // Count and report under one lock so listeners see TilesDone strictly increasing.
          lock (progressLock)
          {
            int d = ++done;
            progress?.Invoke(new RenderProgress(d, tiles.Count, t));
          }
        }
      }
      catch (OperationCanceledException) when (cancel.IsCancellationRequested)
      {
        // User code obeyed the cancellation (Interruption.Poll): the tile stays unfinished.
      }
      catch (Exception e)
      {
        // Tiles in flight may fail differently; report the first in tile order, whatever the threads.
        failure.Report(k, e);
      }
    }

    if (threads == 1)
      Work();
    else
    {
      var workers = new Thread[threads];
      for (int i = 0; i < threads; i++)
      {
        workers[i] = new Thread(Work, WorkerStackSize) { IsBackground = true, Name = $"grcis-render-{i}" };
        workers[i].Start();
      }
      foreach (Thread w in workers)
        w.Join();
    }

    // Publish this render's rays to GrCis's global counters once (workers counted per thread).
    long renderRays = context.Rays - raysBefore;
    Interlocked.Add(ref Intersection.countRays, renderRays);
    Interlocked.Add(ref Intersection.countIntersections, context.Hits - hitsBefore);
    Interlocked.Add(ref Statistics.allRaysCount, (int)Math.Min(renderRays, int.MaxValue));

    if (failure.Exception is Exception e)
      throw new RenderException($"Rendering failed: {e.Message}", e);
    return image;
  }
}
