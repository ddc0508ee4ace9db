using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace Rendering;

/// <summary>
/// The unit cube [0,1]³ (not centred). Texture coordinates are the two local coordinates
/// spanning the face that was hit: (y, z) on ±x faces, (x, z) on ±y faces, (x, y) on ±z faces.
/// </summary>
public class Cube : DefaultSceneNode, ISolid, IRecordSolid
{
  /// <summary>Outward face normals in GrCis's order: +x, −x, +y, −y, +z, −z.</summary>
  protected static readonly Vector3d[] Normals =
  {
    Vector3d.UnitX, -Vector3d.UnitX, Vector3d.UnitY, -Vector3d.UnitY, Vector3d.UnitZ, -Vector3d.UnitZ,
  };

  /// <summary>
  /// The entry and the exit of the line <c>p0 + t * p1</c> (local coordinates) through the cube [0, 1]³, each
  /// with the outward normal of its face, sorted by <see cref="Intersection.T"/>; null on a miss.
  /// </summary>
  public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
  {
    if (!Slabs(p0, p1, out double tMin, out int faceMin, out double tMax, out int faceMax))
      return null;

    var result = new LinkedList<Intersection>();
    result.AddLast(new Intersection(this) { T = tMin, Enter = true, Front = true, CoordLocal = p0 + tMin * p1, NormalLocal = FaceNormal(faceMin) });
    result.AddLast(new Intersection(this) { T = tMax, Enter = false, Front = false, CoordLocal = p0 + tMax * p1, NormalLocal = FaceNormal(faceMax) });
    return result;
  }

  /// <summary>Entry and exit parameters and faces of the line in the cube; false on a miss.</summary>
  static bool Slabs(in Vector3d p0, in Vector3d p1, out double tMin, out int faceMin, out double tMax, out int faceMax)
  {
    tMin = double.NegativeInfinity;
    tMax = double.PositiveInfinity;
    faceMin = faceMax = -1;

    // Slab test, remembering which face bounds the interval on each side.
    for (int axis = 0; axis < 3; axis++)
    {
      double o = p0[axis], d = p1[axis];
      if (d == 0.0)
      {
        if (o <= 0.0 || o >= 1.0)
          return false;
        continue;
      }
      double inv = 1.0 / d;
      double tLow = -o * inv;          // plane coordinate 0
      double tHigh = (1.0 - o) * inv;  // plane coordinate 1
      int faceLow = 2 * axis + 1, faceHigh = 2 * axis;   // face index: 2·axis (+), 2·axis + 1 (−)
      if (inv < 0.0)
      {
        (tLow, tHigh) = (tHigh, tLow);
        (faceLow, faceHigh) = (faceHigh, faceLow);
      }
      if (tLow > tMin)
      {
        tMin = tLow;
        faceMin = faceLow;
      }
      if (tHigh < tMax)
      {
        tMax = tHigh;
        faceMax = faceHigh;
      }
      if (tMin >= tMax)
        return false;
    }
    return faceMin >= 0 && faceMax >= 0;   // both negative: zero direction
  }

  // ---------------------------------------------------------------- fast path (same slabs, same records)

  /// <inheritdoc/>
  public virtual bool RecordsMatchIntersect => Accel.SubclassCheck.KeepsGeometry(this, typeof(Cube));

  /// <inheritdoc/>
  public virtual bool IsClosed => true;

  /// <inheritdoc/>
  public virtual bool IntersectFirst(in Vector3d p0, in Vector3d p1, double len2, out SolidRecord hit, out bool insideBefore)
  {
    hit = default;
    insideBefore = false;
    if (!Slabs(p0, p1, out double tMin, out int faceMin, out double tMax, out int faceMax) ||
        !SolidSupport.FirstOfPair(tMin, tMax, len2, out bool second, out insideBefore))
      return false;
    double t = second ? tMax : tMin;
    hit.T = t;
    hit.CoordLocal = p0 + t * p1;
    hit.Data = second ? faceMax : faceMin;
    hit.Enter = hit.Front = !second;
    return true;
  }

  /// <inheritdoc/>
  public virtual int MaxRecords => 2;

  /// <inheritdoc/>
  public virtual int IntersectAll(in Vector3d p0, in Vector3d p1, Span<SolidRecord> dst)
  {
    if (!Slabs(p0, p1, out double tMin, out int faceMin, out double tMax, out int faceMax))
      return 0;
    dst[0] = new SolidRecord { T = tMin, CoordLocal = p0 + tMin * p1, Data = faceMin, Enter = true, Front = true };
    dst[1] = new SolidRecord { T = tMax, CoordLocal = p0 + tMax * p1, Data = faceMax };
    return 2;
  }

  /// <inheritdoc/>
  public virtual void InitIntersection(in SolidRecord hit, Intersection target)
  {
    target.SetRecord(hit);
    target.NormalLocal = FaceNormal(hit.Data);
  }

  /// <summary>Outward normal of face 2·axis (positive side) or 2·axis + 1 (negative side).</summary>
  internal static Vector3d FaceNormal(int face)
  {
    Vector3d n = Vector3d.Zero;
    n[face >> 1] = (face & 1) == 0 ? 1.0 : -1.0;
    return n;
  }

  /// <summary>Sets the texture coordinates (the two local coordinates of the face, see <see cref="Cube"/>), the face normal and the face's two axes as tangents.</summary>
  public override void CompleteIntersection(Intersection inter)
  {
    Vector3d n = inter.NormalLocal;
    inter.TextureCoord = TextureCoordAt(inter.CoordLocal, n);
    if (n.X != 0.0)
      SolidSupport.SetWorldFrame(inter, n, Vector3d.UnitY, Vector3d.UnitZ);
    else if (n.Y != 0.0)
      SolidSupport.SetWorldFrame(inter, n, Vector3d.UnitX, Vector3d.UnitZ);
    else
      SolidSupport.SetWorldFrame(inter, n, Vector3d.UnitX, Vector3d.UnitY);
  }

  /// <summary>Texture coordinates on the face with normal <paramref name="n"/>: the two coordinates along it.</summary>
  internal static Vector2d TextureCoordAt(in Vector3d p, in Vector3d n) =>
    n.X != 0.0 ? new Vector2d(p.Y, p.Z) : n.Y != 0.0 ? new Vector2d(p.X, p.Z) : new Vector2d(p.X, p.Y);

  /// <summary>The part of <see cref="CompleteIntersection"/> the library's shading reads (same arithmetic): no tangents.</summary>
  internal static void CompleteSurface(Intersection inter, in Matrix4d worldToLocal)
  {
    Vector3d n = inter.NormalLocal;
    inter.TextureCoord = TextureCoordAt(inter.CoordLocal, n);
    inter.Normal = Vector3d.TransformNormalInverse(n, worldToLocal);
  }

  /// <summary>The cube itself: [0, 1]³.</summary>
  /// <param name="corner1">The minimal corner (0, 0, 0).</param>
  /// <param name="corner2">The maximal corner (1, 1, 1).</param>
  public virtual void GetBoundingBox(out Vector3d corner1, out Vector3d corner2)
  {
    corner1 = Vector3d.Zero;
    corner2 = Vector3d.One;
  }
}
