using System;
using System.Threading;
using MathSupport;

namespace Rendering.Execution;

/// <summary>
/// What a worker renders, kept in its <see cref="WorkerContext"/>: the image function and renderer (with the scene,
/// <c>MT.imageFunction</c>, <c>MT.renderer</c>, <c>MT.scene</c>), and <c>WorkerContext.Begin</c>, the one place every
/// kind of worker is made (the tile renderer's, the progressive passes' through it, the coarse preview's, the pixel probe's).
/// </summary>
public static class WorkerRendering
{
  static readonly WorkerSlot<IImageFunction> imageFunction = new();
  static readonly WorkerSlot<IRenderer> renderer = new();

  extension(WorkerContext context)
  {
    /// <summary>What the worker renders: the scene (its clone) (<c>MT.scene</c>).</summary>
    public IRayScene? Scene
    {
      get => WorkerScene.Of(context);
      internal set => WorkerScene.Set(context, value);
    }

    /// <summary>The image function the worker samples (<c>MT.imageFunction</c>).</summary>
    public IImageFunction? ImageFunction
    {
      get => context.Peek(imageFunction);
      internal set => context.Set(imageFunction, value);
    }

    /// <summary>The renderer the worker runs, or null (<c>MT.renderer</c>).</summary>
    public IRenderer? Renderer
    {
      get => context.Peek(renderer);
      internal set => context.Set(renderer, value);
    }
  }

  extension(WorkerContext)
  {
    /// <summary>
    /// Makes the calling thread a worker of <paramref name="render"/> until the scope ends: a new context with its own
    /// clone of the time-dependent parts of <paramref name="scene"/> (<see cref="SceneCloner.ForFrameWorker"/>), a sampler
    /// of <paramref name="options"/>' kind, seed and frame, and <paramref name="cancel"/> for user code. The scene time and
    /// script folder of <paramref name="parent"/> carry over. On disposal the worker's rays and hits are added to the
    /// render's counts and the thread's previous context is back.
    /// </summary>
    /// <param name="render">The render the worker counts for and whose observer, noise and prepared scenes it uses; null = the thread's own prepared scenes, nothing observed or published.</param>
    /// <param name="parent">The context of the thread that started the render (taken there, before the workers start), so every worker sees its scene time and script folder whatever thread it runs on; null = the calling thread's.</param>
    public static WorkerContext.Scope Begin(RenderContext? render, IRayScene scene, IImageFunction imageFunction, IRenderer? renderer, RenderOptions options,
                                            CancellationToken cancel = default, int threadID = 0, WorkerContext? parent = null)
    {
      ArgumentNullException.ThrowIfNull(scene);
      ArgumentNullException.ThrowIfNull(imageFunction);
      ArgumentNullException.ThrowIfNull(options);
      WorkerContext previous = WorkerContext.Current;
      parent ??= previous;
      var c = new WorkerContext(Sampler.Create(options.Sampler, options.Seed, options.Frame))
      {
        ThreadID = threadID,
        Cancel = cancel,
        ScriptDirectory = parent.ScriptDirectory,
        Time = parent.Time,
        // The same thread's stack: user calls under way before the worker began still count.
        RecursionDepth = previous.RecursionDepth,
        Rnd = new RandomJames(),
      };
      c.ImageFunction = imageFunction;
      c.Renderer = renderer;
      var scratch = new ShadingScratch();
      if (render != null)
        scratch.UseRender(render);
      else
        scratch.Queries = ShadingScratch.Of(previous).Queries;
      ShadingScratch.Set(c, scratch);
      WorkerContext.Enter(c);
      try
      {
        // Workers share the frame's scene; only a function that moves time per sample (motion blur) gets each worker its
        // own clone of the time-dependent parts ("clone on write"). Cloned here, so a failure leaves the thread as it was.
        c.Scene = SceneCloner.ForFrameWorker(scene, imageFunction);
      }
      catch
      {
        WorkerContext.Leave(previous);
        throw;
      }
      return new WorkerContext.Scope(previous, c, render == null ? endOwn : (p, w) => End(render, p, w));
    }
  }

  static readonly Action<WorkerContext, WorkerContext> endOwn = (p, w) => End(null, p, w);

  /// <summary>Adds the worker's ray and hit counts to its render and to the thread's previous context.</summary>
  static void End(RenderContext? render, WorkerContext previous, WorkerContext worker)
  {
    ShadingScratch w = ShadingScratch.Of(worker), p = ShadingScratch.Of(previous);
    render?.Add(w.Rays, w.Hits);
    // A thread's own counts include what it traced as a worker (RayCounter.ThreadRays).
    p.Rays += w.Rays;
    p.Hits += w.Hits;
  }
}
