using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>
/// The one interface between shading and geometry: the first hit along a ray, and whether anything blocks a
/// shadow ray. Two implementations answer it with the same hits: <see cref="SceneLists"/>, GrCis's own
/// search (the whole scene's <see cref="IIntersectable.Intersect"/> lists), and <see cref="PreparedScene"/>,
/// the flattened scene with its BVH and allocation-free solid kernels.
/// </summary>
public interface ISceneQuery
{
  /// <summary>The scene (its root intersectable) this query answers for.</summary>
  IIntersectable? Source { get; }

  /// <summary>
  /// The hit <see cref="Intersection.FirstIntersection"/> picks along <c>p0 + t p1</c>, completed as far as
  /// <paramref name="needs"/> says (textures not applied yet), or null. <paramref name="reuse"/>, when given,
  /// may be filled instead of allocating a new intersection.
  /// </summary>
  Intersection? FirstHit(Vector3d p0, Vector3d p1, Intersection? reuse = null, HitData needs = HitData.All);

  /// <summary>
  /// True when a surface not marked <see cref="PropertyName.NO_SHADOW"/> lies between <paramref name="p0"/> and
  /// the light at <c>p0 + dir</c> (GrCis's rule: the first real hit, not beyond <c>t = 1</c>).
  /// </summary>
  bool AnyHit(Vector3d p0, Vector3d dir);
}
