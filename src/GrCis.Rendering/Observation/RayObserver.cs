using OpenTK.Mathematics;

namespace Rendering.Observation;

/// <summary>
/// Receives every ray <see cref="RayTracing"/> (or <see cref="PathTracing"/>, a path as a chain of nested bounces) traces while it is attached to a render
/// (<see cref="Execution.RenderContext.Observer"/>): the demo's probe, extra views and statistics.
/// With none attached the tracer pays one null test per ray. One observer serves all render threads,
/// so implementations keep per-thread or per-pixel state only.
/// </summary>
public abstract class RayObserver
{
  /// <summary>A shaded ray starts (its shadow and secondary rays follow before <see cref="EndRay"/>).</summary>
  public virtual void BeginRay(RayKind kind, int depth, in Vector3d origin, in Vector3d direction) { }

  /// <summary>
  /// A shaded ray is done; <paramref name="hit"/> is its completed first hit, or null for a miss. The hit may be
  /// a pooled object reused by the next ray (copy what is needed, keep no reference), and it carries what the
  /// image function reads (<see cref="Accel.HitData"/>): for the library's shading the surface only (point,
  /// normal, solid, attributes), not the local frame.
  /// </summary>
  public virtual void EndRay(RayKind kind, int depth, in Vector3d origin, in Vector3d direction, Intersection? hit) { }

  /// <summary>A shadow ray towards the light at <c>origin + direction</c>; <paramref name="blocked"/> when no light passes.</summary>
  public virtual void ShadowRay(in Vector3d origin, in Vector3d direction, bool blocked) { }
}
