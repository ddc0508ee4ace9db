using System;
using System.Collections.Generic;
using System.Linq;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Solids;

/// <summary>Small helpers: placing a solid under a transformed parent and checking hit lists.</summary>
internal static class SolidTestSupport
{
  /// <summary>Puts <paramref name="solid"/> into a union root with the given local → world transform.</summary>
  public static CSGInnerNode Place(ISceneNode solid, Matrix4d toWorld)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.InsertChild(solid, toWorld);
    return root;
  }

  public static List<Intersection> Hits(IIntersectable node, Vector3d p0, Vector3d p1) =>
    node.Intersect(p0, p1)?.ToList() ?? new List<Intersection>();

  public static void AssertSorted(IReadOnlyList<Intersection> hits)
  {
    for (int i = 1; i < hits.Count; i++)
      Assert.True(hits[i - 1].T <= hits[i].T, $"hits not sorted at {i}: {hits[i - 1].T} > {hits[i].T}");
  }

  public static void AssertVector(Vector3d expected, Vector3d actual, double tol = 1e-9)
  {
    Assert.True((expected - actual).Length <= tol, $"expected {expected}, got {actual}");
  }

  /// <summary>The world point of a completed hit must lie on the world ray.</summary>
  public static void AssertOnRay(Intersection i, Vector3d p0, Vector3d p1, double tol = 1e-9) =>
    AssertVector(p0 + i.T * p1, i.CoordWorld, tol);

  /// <summary>Completes the first hit in front of the origin and returns it.</summary>
  public static Intersection First(IIntersectable scene, Vector3d p0, Vector3d p1)
  {
    Intersection? i = Intersection.FirstIntersection(scene.Intersect(p0, p1), ref p1);
    Assert.NotNull(i);
    i!.Complete();
    return i;
  }
}
