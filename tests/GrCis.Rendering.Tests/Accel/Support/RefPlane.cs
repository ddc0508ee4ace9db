using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;

namespace GrCis.Testing;

/// <summary>Stand-in for the solids branch's infinite Plane z = 0 (fact sheet §3.5): one record, open.</summary>
public sealed class RefPlane : DefaultSceneNode, IRecordSolid
{
  static bool Hit(in Vector3d p0, in Vector3d p1, out double t, out Vector3d local)
  {
    t = 0.0;
    local = default;
    if (System.Math.Abs(p1.Z) <= double.Epsilon)
      return false;
    t = -p0.Z / p1.Z;
    local = new Vector3d(p0.X + t * p1.X, p0.Y + t * p1.Y, 0.0);
    return true;
  }

  public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
  {
    if (!Hit(p0, p1, out double t, out Vector3d local))
      return null;
    bool front = p1.Z < 0.0;
    var list = new LinkedList<Intersection>();
    list.AddLast(new Intersection(this) { T = t, Enter = front, Front = front, CoordLocal = local });
    return list;
  }

  public bool RecordsMatchIntersect => true;

  // A half-space whose record may lie behind the origin and still leave the ray "inside".
  public bool IsClosed => false;

  public bool IntersectFirst(in Vector3d p0, in Vector3d p1, double len2, out SolidRecord hit, out bool insideBefore)
  {
    hit = default;
    insideBefore = false;
    if (!Hit(p0, p1, out double t, out Vector3d local))
      return false;
    bool front = p1.Z < 0.0;
    if (t > 0.0 && t * t * len2 > Intersection.RAY_EPSILON2)
    {
      insideBefore = !front;
      hit = new SolidRecord { T = t, Enter = front, Front = front, CoordLocal = local };
      return true;
    }
    insideBefore = front;
    return false;
  }

  public void InitIntersection(in SolidRecord hit, Intersection target)
  {
    target.T = hit.T;
    target.Enter = hit.Enter;
    target.Front = hit.Front;
    target.CoordLocal = hit.CoordLocal;
  }

  public override void CompleteIntersection(Intersection inter)
  {
    inter.NormalLocal = Vector3d.UnitZ;
    inter.Normal = Vector3d.TransformNormalInverse(Vector3d.UnitZ, inter.WorldToLocal);
    inter.TextureCoord = new Vector2d(inter.CoordLocal.X, inter.CoordLocal.Y);
  }

  public void GetBoundingBox(out Vector3d corner1, out Vector3d corner2)
  {
    corner1 = new Vector3d(double.NegativeInfinity, double.NegativeInfinity, 0.0);
    corner2 = new Vector3d(double.PositiveInfinity, double.PositiveInfinity, 0.0);
  }
}
