using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Interactive;

/// <summary>
/// Receives every ray an <see cref="InstrumentedRayTracing"/> traces. One observer serves all render
/// threads, so implementations keep per-thread or per-pixel state only.
/// </summary>
internal abstract class RayObserver
{
  /// <summary>Whether rays must be classified (reflected vs refracted); costs a little per ray.</summary>
  public virtual bool NeedsKinds => false;

  /// <summary>A shaded ray starts (its secondary rays follow before <see cref="EndRay"/>).</summary>
  public virtual void BeginRay(RayKind kind, int depth, in Vector3d origin, in Vector3d direction) { }

  /// <summary>A shaded ray is done; <paramref name="hit"/> is its completed first hit, or null for a miss.</summary>
  public virtual void EndRay(RayKind kind, int depth, in Vector3d origin, in Vector3d direction, Intersection? hit) { }

  /// <summary>A shadow ray towards the light at <c>origin + direction</c>.</summary>
  public virtual void ShadowRay(in Vector3d origin, in Vector3d direction, bool blocked) { }
}
