using System;
using System.Threading;
using Rendering.Accel;
using Rendering.Observation;

namespace Rendering.Execution;

/// <summary>
/// What one render carries besides its options: the observer its rays are reported to, and the rays and
/// hits its threads counted. A thread shades under a context between <see cref="Enter"/> and the scope's
/// end (<see cref="TileRenderer"/> enters it on every worker); GrCis's own API has no context parameter,
/// so the shading code finds it through the thread's shading state.
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

  /// <summary>Shades the calling thread's rays under this context until the scope is disposed.</summary>
  public Scope Enter()
  {
    ShadingScratch s = ShadingScratch.Current;
    var scope = new Scope(this, s, s.Observer, s.Queries, s.LastPrepared, s.Noise, s.Rays, s.Hits);
    s.Observer = Observer;
    s.Noise = Noise;
    s.Queries = Queries;
    s.LastPrepared = null;
    return scope;
  }

  /// <summary>A thread's time under a context: on disposal its counts are added and the previous observer restored.</summary>
  public readonly struct Scope : IDisposable
  {
    readonly RenderContext? context;
    readonly ShadingScratch? scratch;
    readonly RayObserver? previous;
    readonly SceneQueries? previousQueries;
    readonly PreparedScene? previousLast;
    readonly NoiseImage? previousNoise;
    readonly long rays0, hits0;

    internal Scope(RenderContext context, ShadingScratch scratch, RayObserver? previous, SceneQueries previousQueries, PreparedScene? previousLast,
                   NoiseImage? previousNoise, long rays0, long hits0)
    {
      this.context = context;
      this.scratch = scratch;
      this.previous = previous;
      this.previousQueries = previousQueries;
      this.previousLast = previousLast;
      this.previousNoise = previousNoise;
      this.rays0 = rays0;
      this.hits0 = hits0;
    }

    public void Dispose()
    {
      if (context == null || scratch == null)
        return;
      Interlocked.Add(ref context.rays, scratch.Rays - rays0);
      Interlocked.Add(ref context.hits, scratch.Hits - hits0);
      scratch.Observer = previous;
      scratch.Queries = previousQueries!;
      scratch.LastPrepared = previousLast;
      scratch.Noise = previousNoise;
    }
  }
}
