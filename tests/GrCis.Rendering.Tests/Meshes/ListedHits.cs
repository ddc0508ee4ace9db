using System.Collections.Generic;
using Rendering;

namespace GrCis.Rendering.Tests.Meshes;

/// <summary>
/// The mesh tests' oracle: what <see cref="MeshBvh"/>'s searches must answer, picked from the hits of every triangle
/// tested one by one.
/// </summary>
internal static class ListedHits
{
  /// <summary>Whether <see cref="Intersection.FirstIntersection"/> accepts a hit at <paramref name="t"/>.</summary>
  public static bool Accepted(double t, double len2) => t > 0.0 && t * t * len2 > Intersection.RAY_EPSILON2;

  /// <summary>The first accepted hit by T, then triangle (<paramref name="accepted"/>), or the last rejected one.</summary>
  public static bool Nearest(List<MeshHit> hits, double len2, bool accepted, out MeshHit best)
  {
    best = default;
    bool found = false;
    foreach (MeshHit h in hits)
    {
      if (Accepted(h.T, len2) != accepted)
        continue;
      bool better = accepted
        ? h.T < best.T || (h.T == best.T && h.Triangle < best.Triangle)
        : h.T > best.T || (h.T == best.T && h.Triangle > best.Triangle);
      if (!found || better)
      {
        best = h;
        found = true;
      }
    }
    return found;
  }
}
