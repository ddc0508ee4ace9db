using System;
using System.Threading;
using Rendering.Accel;
using Rendering.Observation;

namespace Rendering.Execution;

/// <summary>
/// What one render carries besides its options: the observer its rays are reported to, and the rays and
/// hits its threads counted. A render's workers shade under it (<c>WorkerContext.Begin</c>), and any thread
/// between <see cref="Enter"/> and the scope's end; GrCis's own API has no context parameter, so the shading code
/// finds it through the thread's <see cref="WorkerContext"/>.
/// </summary>
public sealed class RenderContext
{
  long rays, hits;

  /// <summary>Receives every ray the render's <see cref="RayTracing"/> traces; null = none (no cost).</summary>
  public RayObserver? Observer { get; init; }

  /// <summary>Receives the pixels' noise estimates (<see cref="SupersamplingImageSynthesizer"/>); null = none taken.</summary>
  public NoiseImage? Noise { get; init; }

  /// <summary>The render's prepared scenes (fresh for each context unless shared, as a preview pass shares its render's).</summary>
  public SceneQueries Queries { get; init; } = new();

  /// <summary>Rays traced under this context by the scopes that have ended (shadow rays included).</summary>
  public long Rays => Interlocked.Read(ref rays);

  /// <summary>Of those, rays that hit something (a blocked shadow ray counts as a hit).</summary>
  public long Hits => Interlocked.Read(ref hits);

  /// <summary>Adds a worker's counts (at the end of its time under this context).</summary>
  internal void Add(long workerRays, long workerHits)
  {
    Interlocked.Add(ref rays, workerRays);
    Interlocked.Add(ref hits, workerHits);
  }

  /// <summary>
  /// Shades the calling thread's rays under this context until the scope is disposed: the thread's
  /// <see cref="WorkerContext"/> takes a shading scratch of this render (its observer, noise and prepared scenes)
  /// and gets its previous one back at the end.
  /// </summary>
  public Scope Enter()
  {
    WorkerContext worker = WorkerContext.Current;
    ShadingScratch previous = ShadingScratch.Of(worker);
    var s = new ShadingScratch();
    s.UseRender(this);
    ShadingScratch.Set(worker, s);
    return new Scope(this, worker, previous, s);
  }

  /// <summary>A thread's time under a context: on disposal its counts are added and the previous scratch restored.</summary>
  public readonly struct Scope : IDisposable
  {
    readonly RenderContext? context;
    readonly WorkerContext? worker;
    readonly ShadingScratch? previous, scratch;

    internal Scope(RenderContext context, WorkerContext worker, ShadingScratch previous, ShadingScratch scratch)
    {
      this.context = context;
      this.worker = worker;
      this.previous = previous;
      this.scratch = scratch;
    }

    /// <summary>Adds the thread's counts under this scope to the render (and to the enclosing scope) and gives the thread its previous scratch back.</summary>
    public void Dispose()
    {
      if (context == null || worker == null || previous == null || scratch == null)
        return;
      context.Add(scratch.Rays, scratch.Hits);
      // The enclosing scope's count includes what was traced inside (same thread, nested).
      previous.Rays += scratch.Rays;
      previous.Hits += scratch.Hits;
      ShadingScratch.Set(worker, previous);
    }
  }
}
