using System.Collections.Generic;
using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>
/// A query of the faithful path (<see cref="AccelMode.None"/>). GrCis had no search structures at all,
/// so while such a query runs on a thread a <see cref="TriangleMesh"/> tests every triangle, as GrCis
/// did; the fast path, and the list members it asks, keep the mesh's BVH. Same hits either way.
/// </summary>
internal static class ExhaustiveSearch
{
  /// <summary>True while a faithful query runs on this thread (kept in the thread's shading state).</summary>
  public static bool Active => ShadingScratch.Current.ExhaustiveSearch;

  /// <summary>All records of <paramref name="node"/> along <c>p0 + t p1</c>, searched as GrCis did.</summary>
  public static LinkedList<Intersection>? Intersect(IIntersectable? node, in Vector3d p0, in Vector3d p1)
  {
    if (node == null)
      return null;
    ShadingScratch scratch = ShadingScratch.Current;
    bool outer = scratch.ExhaustiveSearch;
    scratch.ExhaustiveSearch = true;
    try
    {
      return node.Intersect(p0, p1);
    }
    finally
    {
      scratch.ExhaustiveSearch = outer;
    }
  }
}
