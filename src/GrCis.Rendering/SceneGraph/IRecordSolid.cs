using System;
using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>
/// Optional allocation-free twin of <see cref="IIntersectable.Intersect"/> for a solid the library knows.
/// Both must describe the same sorted record list; the fast path then gives the same image as the
/// faithful one. A subclass that overrides <c>Intersect</c> must report <see cref="RecordsMatchIntersect"/> false.
/// </summary>
public interface IRecordSolid : ISolid
{
  /// <summary>False when this instance's records may differ from <see cref="IntersectFirst"/> (e.g. a script subclass).</summary>
  bool RecordsMatchIntersect { get; }

  /// <summary>
  /// True when every record lies inside the bounding box and the list starts outside the solid
  /// (balanced Enter/exit pairs), so a ray whose box interval is behind its origin sees "outside".
  /// Only closed solids may live in the BVH; open ones (planes) are tested for every ray.
  /// </summary>
  bool IsClosed { get; }

  /// <summary>
  /// The first record of the local ray <c>p0 + t p1</c> that <see cref="Intersection.FirstIntersection"/>
  /// accepts: <c>T &gt; 0 &amp;&amp; T² · <paramref name="len2"/> &gt; RAY_EPSILON2</c>, where
  /// <paramref name="len2"/> is |p1|² of the WORLD ray. <paramref name="insideBefore"/> is the CSG inside
  /// state just before that record: <c>!first.Enter</c> of the whole list, then each skipped record's Enter.
  /// Returns false (and still sets <paramref name="insideBefore"/>) when no record is accepted.
  /// </summary>
  bool IntersectFirst(in Vector3d p0, in Vector3d p1, double len2, out SolidRecord hit, out bool insideBefore);

  /// <summary>
  /// Fills the cheap part (T, Enter, Front, local coordinates and normal, solid data) of a fresh or reset
  /// <paramref name="target"/> whose <see cref="Intersection.Solid"/> is this solid, exactly as <c>Intersect</c>
  /// would have listed the record (not completed).
  /// </summary>
  void InitIntersection(in SolidRecord hit, Intersection target);

  /// <summary>
  /// Upper bound on the records <see cref="IntersectAll"/> writes for any ray; -1 when unknown (meshes),
  /// which keeps CSG subtrees over this solid on the list path.
  /// </summary>
  int MaxRecords => -1;

  /// <summary>
  /// Writes every record of the local ray <c>p0 + t p1</c> into <paramref name="dst"/> (at least
  /// <see cref="MaxRecords"/> long) in the order and with the bits <c>Intersect</c> would list them
  /// (T, Enter, Front, local coordinates, solid data), without allocating; returns the count, or -1
  /// when this solid cannot (then <see cref="MaxRecords"/> is -1 too). For the CSG kernel (<see cref="CsgKernel"/>).
  /// </summary>
  int IntersectAll(in Vector3d p0, in Vector3d p1, Span<SolidRecord> dst) => -1;

  /// <summary>The <see cref="Intersection"/> that <c>Intersect</c> would have listed for this record (not completed).</summary>
  Intersection CreateIntersection(in SolidRecord hit)
  {
    var i = new Intersection(this);
    InitIntersection(hit, i);
    return i;
  }
}
