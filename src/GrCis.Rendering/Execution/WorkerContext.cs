using System;
using System.Collections.Generic;
using System.ComponentModel;
using System.Runtime.CompilerServices;
using System.Threading;
using MathSupport;

namespace Rendering.Execution;

/// <summary>
/// Everything one render worker works with, in one object: its clone of the scene, its <see cref="Sampler"/> (which
/// also holds the current pixel and sample), its shading scratch (ray and hit counts, observer, prepared scenes,
/// pooled objects), the cancellation its user code obeys, the script folder data files are looked up in, and the
/// caches of its image function and solids. Built in one place, <see cref="Begin"/>, by every kind of worker (the
/// tile renderer's, the progressive passes' through it, the coarse preview's, the pixel probe's). GrCis's API has
/// no context parameter, so a thread finds its context in the one thread static, <see cref="Current"/>; GrCis's
/// <see cref="MT"/> statics read and write it. A thread that never began one (the main thread, a student's own)
/// gets a default context of its own on first use.
/// </summary>
public sealed class WorkerContext
{
  [ThreadStatic] static WorkerContext? current;

  /// <summary>The calling thread's context.</summary>
  public static WorkerContext Current
  {
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    get => current ?? CreateDefault();
  }

  [MethodImpl(MethodImplOptions.NoInlining)]
  static WorkerContext CreateDefault() => current = new WorkerContext(new CorrelatedMultiJitterSampler(), null);

  WorkerContext(Sampler sampler, RenderContext? render)
  {
    Sampler = sampler;
    Scratch = new ShadingScratch();
    if (render != null)
      Scratch.UseRender(render);
  }

  /// <summary>The worker's sample generator and current pixel sample.</summary>
  public Sampler Sampler { get; }

  /// <summary>What the worker renders: the scene (its clone), the image function and the renderer (<c>MT.scene</c> ...).</summary>
  public IRayScene? Scene { get; internal set; }

  /// <summary>The image function the worker samples (<c>MT.imageFunction</c>).</summary>
  public IImageFunction? ImageFunction { get; internal set; }

  /// <summary>The renderer the worker runs, or null (<c>MT.renderer</c>).</summary>
  public IRenderer? Renderer { get; internal set; }

  /// <summary>Index of the worker among its render's threads (<c>MT.threadID</c>).</summary>
  public int ThreadID { get; internal set; }

  /// <summary>The cancellation user code on this worker obeys (<see cref="Interruption"/>).</summary>
  public CancellationToken Cancellation => Cancel;

  // GrCis's per-thread values behind MT (fields: MT's properties are on hot paths).
  internal RandomJames? Rnd;
  internal double DoubleX, DoubleY, Time;
  internal ulong PixelHash;

  internal CancellationToken Cancel;

  /// <summary>
  /// How many calls of user code are under way on this thread. The recursion guards compiled into user code count
  /// them (<see cref="Recursion.Enter"/> up, the guard's <c>finally</c> down, inline: a field, not a call, as user
  /// code is not optimised); nothing else writes it.
  /// </summary>
  [EditorBrowsable(EditorBrowsableState.Never)]
  public int RecursionDepth;

  /// <summary>Folder of the script whose code runs here (<see cref="Utilities.DataFiles"/>).</summary>
  internal string? ScriptDirectory;

  /// <summary>The shading scratch of the render this worker shades for (swapped by <see cref="RenderContext.Enter"/>).</summary>
  internal ShadingScratch Scratch;

  // PathTracing's lights of the scene this worker renders, rebuilt when the scene, its lights, its snapshot or the frame changes.
  internal SceneLights? Lights;
  internal object? LightsScene, LightsSources, LightsRoot, LightsSnapshot;
  internal int LightsFrame;

  /// <summary>The rays of the path being observed, ended in reverse order when the path is done (<see cref="PathTracing"/>).</summary>
  internal (Observation.RayKind Kind, int Depth, OpenTK.Mathematics.Vector3d Origin, OpenTK.Mathematics.Vector3d Direction, Intersection? Hit)[]? ObservedRays;

  /// <summary>The crossings a <see cref="TriangleMesh"/> query collects (one query at a time per worker).</summary>
  internal List<MeshHit>? MeshHits;

  // Result buffers of attenuated lights, one per light (PointLightSource.Attenuated): few lights, a linear search.
  object?[] lightOwners = new object?[4];
  double[]?[] lightBuffers = new double[]?[4];

  /// <summary>The worker's buffer of <paramref name="bands"/> values for light <paramref name="owner"/>.</summary>
  internal double[] LightBuffer(object owner, int bands)
  {
    int i = 0;
    for (; i < lightOwners.Length && lightOwners[i] != null; i++)
      if (ReferenceEquals(lightOwners[i], owner))
      {
        double[] b = lightBuffers[i]!;
        return b.Length == bands ? b : lightBuffers[i] = new double[bands];
      }
    if (i == lightOwners.Length && i >= 64)
    {
      // A long-lived thread meets new lights with every scene: forget the old ones (their buffers stay valid for their callers).
      Array.Clear(lightOwners);
      Array.Clear(lightBuffers);
      i = 0;
    }
    else if (i == lightOwners.Length)
    {
      Array.Resize(ref lightOwners, 2 * i);
      Array.Resize(ref lightBuffers, 2 * i);
    }
    lightOwners[i] = owner;
    return lightBuffers[i] = new double[bands];
  }

  /// <summary>
  /// Makes the calling thread a worker of <paramref name="render"/> until the scope ends: a new context with its own
  /// clone of the time-dependent parts of <paramref name="scene"/> (<see cref="SceneCloner.ForFrameWorker"/>), a sampler
  /// of <paramref name="options"/>' kind, seed and frame, and <paramref name="cancel"/> for user code. The scene time and
  /// script folder of <paramref name="parent"/> carry over. On disposal the worker's rays and hits are added to the
  /// render's counts and the thread's previous context is back.
  /// </summary>
  /// <param name="render">The render the worker counts for and whose observer, noise and prepared scenes it uses; null = the thread's own prepared scenes, nothing observed or published.</param>
  /// <param name="parent">The context of the thread that started the render (taken there, before the workers start), so every worker sees its scene time and script folder whatever thread it runs on; null = the calling thread's.</param>
  public static Scope Begin(RenderContext? render, IRayScene scene, IImageFunction imageFunction, IRenderer? renderer, RenderOptions options,
                            CancellationToken cancel = default, int threadID = 0, WorkerContext? parent = null)
  {
    ArgumentNullException.ThrowIfNull(scene);
    ArgumentNullException.ThrowIfNull(imageFunction);
    ArgumentNullException.ThrowIfNull(options);
    WorkerContext previous = Current;
    parent ??= previous;
    var c = new WorkerContext(Sampler.Create(options.Sampler, options.Seed, options.Frame), render)
    {
      ImageFunction = imageFunction,
      Renderer = renderer,
      ThreadID = threadID,
      Cancel = cancel,
      ScriptDirectory = parent.ScriptDirectory,
      Time = parent.Time,
      // The same thread's stack: user calls under way before the worker began still count.
      RecursionDepth = previous.RecursionDepth,
      Rnd = new RandomJames(),
    };
    if (render == null)
      c.Scratch.Queries = previous.Scratch.Queries;
    current = c;
    try
    {
      // Workers share the frame's scene; only a function that moves time per sample (motion blur) gets each worker its
      // own clone of the time-dependent parts ("clone on write"). Cloned here, so a failure leaves the thread as it was.
      c.Scene = SceneCloner.ForFrameWorker(scene, imageFunction);
    }
    catch
    {
      current = previous;
      throw;
    }
    return new Scope(previous, c, render);
  }

  /// <summary>Shades under <paramref name="render"/> (its observer, noise and prepared scenes) until the scope ends; the rest of the context stays.</summary>
  internal RenderContext.Scope EnterRender(RenderContext render)
  {
    ShadingScratch previous = Scratch;
    var s = new ShadingScratch();
    s.UseRender(render);
    Scratch = s;
    return new RenderContext.Scope(render, this, previous, s);
  }

  /// <summary>A worker's time: on disposal its counts go to the render and the thread's previous context is back.</summary>
  public readonly struct Scope : IDisposable
  {
    readonly WorkerContext? previous, worker;
    readonly RenderContext? render;

    internal Scope(WorkerContext previous, WorkerContext worker, RenderContext? render)
    {
      this.previous = previous;
      this.worker = worker;
      this.render = render;
    }

    /// <summary>The worker's context.</summary>
    public WorkerContext? Context => worker;

    /// <summary>Adds the worker's ray and hit counts to its render and to the thread's previous context, and makes that context current again.</summary>
    public void Dispose()
    {
      if (worker == null || previous == null)
        return;
      render?.Add(worker.Scratch.Rays, worker.Scratch.Hits);
      // A thread's own counts include what it traced as a worker (RayCounter.ThreadRays).
      previous.Scratch.Rays += worker.Scratch.Rays;
      previous.Scratch.Hits += worker.Scratch.Hits;
      current = previous;
    }
  }
}
