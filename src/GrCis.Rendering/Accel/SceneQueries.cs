using System.Runtime.CompilerServices;

namespace Rendering.Accel;

/// <summary>
/// The prepared scenes of one render, one per scene root (each worker's clone of a time-dependent scene has its
/// own): kept by the render's <see cref="Execution.RenderContext"/>, so image functions hold no caches and a new
/// render starts from fresh snapshots. A root that is no longer used is not kept alive.
/// </summary>
public sealed class SceneQueries
{
  readonly ConditionalWeakTable<IIntersectable, PreparedScene> prepared = new();

  /// <summary>The snapshot of <paramref name="source"/>, prepared on first use (thread-safe).</summary>
  public PreparedScene For(IIntersectable source) => prepared.GetValue(source, static s => PreparedScene.Prepare(s));

  /// <summary>A new snapshot of <paramref name="source"/> (the scene graph may have changed), kept from now on.</summary>
  public PreparedScene Prepare(IIntersectable source)
  {
    PreparedScene ps = PreparedScene.Prepare(source);
    prepared.AddOrUpdate(source, ps);
    return ps;
  }
}
