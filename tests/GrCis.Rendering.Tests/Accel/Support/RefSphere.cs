using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;

namespace GrCis.Testing;

/// <summary>
/// Stand-in for the solids branch's Sphere (GrCis unit sphere, fact sheet §3.1) with both APIs sharing
/// one root computation, as the real solids are expected to. Used until the solids land.
/// </summary>
public sealed class RefSphere : DefaultSceneNode, IRecordSolid
{
  static bool Roots(in Vector3d p0, in Vector3d p1, out double t1, out double t2)
  {
    double od = Vector3d.Dot(p0, p1), dd = Vector3d.Dot(p1, p1), oo = Vector3d.Dot(p0, p0);
    double disc = od * od + dd * (1.0 - oo);
    if (disc <= 0.0)
    {
      t1 = t2 = 0.0;
      return false;
    }
    disc = Math.Sqrt(disc);
    t1 = (-od - disc) / dd;
    t2 = (-od + disc) / dd;
    return true;
  }

  public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
  {
    if (!Roots(p0, p1, out double t1, out double t2))
      return null;
    var list = new LinkedList<Intersection>();
    list.AddLast(new Intersection(this) { T = t1, Enter = true, Front = true, CoordLocal = p0 + t1 * p1 });
    list.AddLast(new Intersection(this) { T = t2, Enter = false, Front = false, CoordLocal = p0 + t2 * p1 });
    return list;
  }

  public bool RecordsMatchIntersect => true;

  public bool IsClosed => true;

  public bool IntersectFirst(in Vector3d p0, in Vector3d p1, double len2, out SolidRecord hit, out bool insideBefore)
  {
    hit = default;
    insideBefore = false;
    if (!Roots(p0, p1, out double t1, out double t2))
      return false;
    if (t1 > 0.0 && t1 * t1 * len2 > Intersection.RAY_EPSILON2)
    {
      hit = new SolidRecord { T = t1, Enter = true, Front = true, CoordLocal = p0 + t1 * p1 };
      return true;
    }
    insideBefore = true;
    if (t2 > 0.0 && t2 * t2 * len2 > Intersection.RAY_EPSILON2)
    {
      hit = new SolidRecord { T = t2, Enter = false, Front = false, CoordLocal = p0 + t2 * p1 };
      return true;
    }
    insideBefore = false;
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
    inter.NormalLocal = inter.CoordLocal;
    inter.Normal = Vector3d.TransformNormalInverse(inter.CoordLocal, inter.WorldToLocal);
    Vector3d c = inter.CoordLocal;
    double r = Math.Sqrt(c.X * c.X + c.Y * c.Y);
    double u = r < 1e-12 ? 0.0 : Math.Atan2(c.Y, c.X) / (2.0 * Math.PI) + 0.5;
    double v = Math.Atan2(r, c.Z) / Math.PI;
    inter.TextureCoord = new Vector2d(u, v);
  }

  public void GetBoundingBox(out Vector3d corner1, out Vector3d corner2)
  {
    corner1 = new Vector3d(-1.0);
    corner2 = new Vector3d(1.0);
  }
}
