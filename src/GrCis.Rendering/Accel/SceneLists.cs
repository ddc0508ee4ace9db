using System.Collections.Generic;
using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>
/// GrCis's own search as a <see cref="ISceneQuery"/> (<c>--accel none</c>): every query asks the whole scene
/// for its sorted <see cref="Intersection"/> list, with no search structure anywhere (a mesh tests every
/// triangle, see <see cref="ExhaustiveSearch"/>). Hits are always completed fully.
/// </summary>
public sealed class SceneLists : ISceneQuery
{
  /// <summary>The list search of the scene whose root is <paramref name="source"/>.</summary>
  /// <param name="source">The scene's root (<see cref="IRayScene.Intersectable"/>), or null for an empty scene.</param>
  public SceneLists(IIntersectable? source) => Source = source;

  /// <summary>The scene's root that every query asks.</summary>
  public IIntersectable? Source { get; }

  /// <inheritdoc/>
  public Intersection? FirstHit(Vector3d p0, Vector3d p1, Intersection? reuse = null, HitData needs = HitData.All)
  {
    LinkedList<Intersection>? list = ExhaustiveSearch.Intersect(Source, p0, p1);
    return Intersection.FirstIntersection(list, ref p1);
  }

  /// <inheritdoc/>
  public bool AnyHit(Vector3d p0, Vector3d dir)
  {
    LinkedList<Intersection>? list = ExhaustiveSearch.Intersect(Source, p0, dir);
    Intersection? si = Intersection.FirstRealIntersection(list, ref dir);
    return si != null && !si.Far(1.0, ref dir);
  }

  /// <summary>Every record along the ray, in GrCis's order (for transparent shadows and user code).</summary>
  public LinkedList<Intersection>? AllHits(Vector3d p0, Vector3d p1) => ExhaustiveSearch.Intersect(Source, p0, p1);
}
