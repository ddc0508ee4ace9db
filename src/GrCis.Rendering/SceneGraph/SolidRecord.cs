using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>
/// The cheap part of one ray–solid record, as a value: what <see cref="IRecordSolid.CreateIntersection"/>
/// needs to build the same <see cref="Intersection"/> the solid's <c>Intersect</c> would have listed.
/// </summary>
public struct SolidRecord
{
  /// <summary>Ray parameter (the same for local and world rays: transforms are affine).</summary>
  public double T;

  /// <summary>The hit point in the solid's local coordinates.</summary>
  public Vector3d CoordLocal;

  /// <summary>Solid-specific payload (face, cap, patch index …).</summary>
  public int Data;

  /// <summary>Second solid-specific payload (e.g. the local ray direction some solids keep).</summary>
  public Vector3d Aux;

  /// <summary>The ray enters the solid here (<see cref="Intersection.Enter"/>).</summary>
  public bool Enter;
  /// <summary>The ray hits the surface from its front (<see cref="Intersection.Front"/>).</summary>
  public bool Front;
}
