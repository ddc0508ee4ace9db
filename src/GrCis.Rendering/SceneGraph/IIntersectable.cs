using System.Collections.Generic;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>Anything a ray can hit.</summary>
public interface IIntersectable
{
  /// <summary>
  /// All intersections of the ray <c>p0 + t * p1</c> (t may be negative; callers skip those),
  /// sorted by <see cref="Intersection.T"/>, or null when there are none. CSG needs them all.
  /// </summary>
  LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1);

  /// <summary>Fills the deferred fields of an intersection this object produced (normal, texture coordinates).</summary>
  void CompleteIntersection(Intersection inter);
}
