using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace Rendering;

/// <summary>
/// The unit sphere centred at the local origin. Texture coordinates: u = longitude about
/// the z axis in [0, 1), v = polar angle / π (0 at the +z pole, 1 at the −z pole).
/// </summary>
public class Sphere : DefaultSceneNode, ISolid, IRecordSolid
{
  /// <summary>
  /// Both points where the line <c>p0 + t * p1</c> (local coordinates) crosses the unit sphere: the entry and
  /// the exit, sorted by <see cref="Intersection.T"/> (negative T included); null on a miss or a mere touch.
  /// </summary>
  public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
  {
    if (!Roots(p0, p1, out double t0, out double t1))
      return null;

    var result = new LinkedList<Intersection>();
    Vector3d c0 = p0 + t0 * p1;
    result.AddLast(new Intersection(this) { T = t0, Enter = true, Front = true, CoordLocal = c0, NormalLocal = c0 });
    Vector3d c1 = p0 + t1 * p1;
    result.AddLast(new Intersection(this) { T = t1, Enter = false, Front = false, CoordLocal = c1, NormalLocal = c1 });
    return result;
  }

  /// <summary>Both parameters where the line meets the unit sphere (t0 &lt; t1); false on a miss or a touch.</summary>
  protected static bool Roots(Vector3d p0, Vector3d p1, out double t0, out double t1)
  {
    // Quadratic |p0 + t p1|² = 1; the discriminant from the closest point, free of cancellation.
    double dd = Vector3d.Dot(p1, p1);
    double od = Vector3d.Dot(p0, p1);
    double oo = Vector3d.Dot(p0, p0);
    t0 = t1 = 0.0;
    if (dd == 0.0)
      return false;
    Vector3d closest = p0 - (od / dd) * p1;
    double disc = dd * (1.0 - closest.LengthSquared);
    return SolidSupport.SolveQuadratic(dd, od, oo - 1.0, disc, out t0, out t1);
  }

  // ---------------------------------------------------------------- fast path (same Roots, same records)

  /// <inheritdoc/>
  public virtual bool RecordsMatchIntersect => Accel.SubclassCheck.KeepsGeometry(this, typeof(Sphere));

  /// <inheritdoc/>
  public virtual bool IsClosed => true;

  /// <inheritdoc/>
  public virtual bool IntersectFirst(in Vector3d p0, in Vector3d p1, double len2, out SolidRecord hit, out bool insideBefore) =>
    First(p0, p1, len2, out hit, out insideBefore);

  /// <summary><see cref="IntersectFirst"/> of this class itself: the prepared query calls it directly for a member of exactly this type.</summary>
  internal bool First(in Vector3d p0, in Vector3d p1, double len2, out SolidRecord hit, out bool insideBefore)
  {
    hit = default;
    insideBefore = false;
    if (!Roots(p0, p1, out double t0, out double t1) ||
        !SolidSupport.FirstOfPair(t0, t1, len2, out bool second, out insideBefore))
      return false;
    double t = second ? t1 : t0;
    hit.T = t;
    hit.CoordLocal = p0 + t * p1;
    hit.Enter = hit.Front = !second;
    return true;
  }

  /// <inheritdoc/>
  public virtual int MaxRecords => 2;

  /// <inheritdoc/>
  public virtual int IntersectAll(in Vector3d p0, in Vector3d p1, Span<SolidRecord> dst)
  {
    if (!Roots(p0, p1, out double t0, out double t1))
      return 0;
    dst[0] = new SolidRecord { T = t0, CoordLocal = p0 + t0 * p1, Enter = true, Front = true };
    dst[1] = new SolidRecord { T = t1, CoordLocal = p0 + t1 * p1 };
    return 2;
  }

  /// <inheritdoc/>
  public virtual void InitIntersection(in SolidRecord hit, Intersection target) => Init(hit, target);

  /// <summary><see cref="InitIntersection"/> of this class itself (called directly, inlined, for exactly this type).</summary>
  [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
  internal static void Init(in SolidRecord hit, Intersection target)
  {
    target.SetRecord(hit);
    target.NormalLocal = hit.CoordLocal;
  }

  /// <summary>
  /// Sets the texture coordinates (see <see cref="Sphere"/>), the normal (the hit point itself, pointing out)
  /// and the tangents along growing u and v; at a pole any pair of tangents.
  /// </summary>
  public override void CompleteIntersection(Intersection inter)
  {
    Vector3d p = inter.CoordLocal;
    double r = Math.Sqrt(p.X * p.X + p.Y * p.Y);
    inter.TextureCoord = TextureCoordAt(p, r);

    // Tangents along growing u (east) and growing v (towards −z).
    if (r > 0.0)
      SolidSupport.SetWorldFrame(inter, p, new Vector3d(-p.Y, p.X, 0.0), new Vector3d(p.X * p.Z / r, p.Y * p.Z / r, -r));
    else
      SolidSupport.SetWorldFrame(inter, p);
  }

  /// <summary>Longitude and colatitude/π of local point <paramref name="p"/> (<paramref name="r"/>: its distance from the z axis).</summary>
  internal static Vector2d TextureCoordAt(in Vector3d p, double r) =>
    new(SolidSupport.Longitude(p.X, p.Y), Math.Atan2(r, p.Z) / Math.PI);

  /// <summary>
  /// The part of <see cref="CompleteIntersection"/> the library's shading reads (same arithmetic): the normal,
  /// and the texture coordinates only when a texture reads them. No tangents.
  /// </summary>
  internal static void CompleteSurface(Intersection inter, in Matrix4d worldToLocal, bool textureCoord)
  {
    Vector3d p = inter.CoordLocal;
    if (textureCoord)
      inter.TextureCoord = TextureCoordAt(p, Math.Sqrt(p.X * p.X + p.Y * p.Y));
    inter.NormalLocal = p;
    inter.Normal = Vector3d.TransformNormalInverse(p, worldToLocal);
  }

  /// <summary>The box [−1, 1]³ around the unit sphere.</summary>
  /// <param name="corner1">The minimal corner (−1, −1, −1).</param>
  /// <param name="corner2">The maximal corner (1, 1, 1).</param>
  public virtual void GetBoundingBox(out Vector3d corner1, out Vector3d corner2)
  {
    corner1 = new Vector3d(-1.0, -1.0, -1.0);
    corner2 = new Vector3d(1.0, 1.0, 1.0);
  }
}
