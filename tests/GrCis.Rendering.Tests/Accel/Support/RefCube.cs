using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;

namespace GrCis.Testing;

/// <summary>Stand-in for the solids branch's Cube: the unit cube [0,1]³ (fact sheet §3.4).</summary>
public sealed class RefCube : DefaultSceneNode, IRecordSolid
{
  // Faces: +X, −X, +Y, −Y, +Z, −Z.
  static readonly Vector3d[] Normals =
  {
    new(1, 0, 0), new(-1, 0, 0), new(0, 1, 0), new(0, -1, 0), new(0, 0, 1), new(0, 0, -1),
  };

  static bool Slabs(in Vector3d p0, in Vector3d p1, out double tMin, out int fMin, out double tMax, out int fMax)
  {
    tMin = double.NegativeInfinity;
    tMax = double.PositiveInfinity;
    fMin = fMax = 0;
    for (int a = 0; a < 3; a++)
    {
      double o = p0[a], d = p1[a];
      if (System.Math.Abs(d) <= double.Epsilon)
      {
        if (o <= 0.0 || o >= 1.0)
          return false;
        continue;
      }
      double ta = -o / d, tb = (1.0 - o) / d;
      int fa = 2 * a + 1, fb = 2 * a;
      if (d < 0.0)
      {
        (ta, tb) = (tb, ta);
        (fa, fb) = (fb, fa);
      }
      if (ta > tMin)
      {
        tMin = ta;
        fMin = fa;
      }
      if (tb < tMax)
      {
        tMax = tb;
        fMax = fb;
      }
    }
    return tMin < tMax;
  }

  public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
  {
    if (!Slabs(p0, p1, out double t1, out int f1, out double t2, out int f2))
      return null;
    var list = new LinkedList<Intersection>();
    list.AddLast(new Intersection(this) { T = t1, Enter = true, Front = true, CoordLocal = p0 + t1 * p1, SolidData = f1 });
    list.AddLast(new Intersection(this) { T = t2, Enter = false, Front = false, CoordLocal = p0 + t2 * p1, SolidData = f2 });
    return list;
  }

  public bool RecordsMatchIntersect => true;

  public bool IsClosed => true;

  public bool IntersectFirst(in Vector3d p0, in Vector3d p1, double len2, out SolidRecord hit, out bool insideBefore)
  {
    hit = default;
    insideBefore = false;
    if (!Slabs(p0, p1, out double t1, out int f1, out double t2, out int f2))
      return false;
    if (t1 > 0.0 && t1 * t1 * len2 > Intersection.RAY_EPSILON2)
    {
      hit = new SolidRecord { T = t1, Enter = true, Front = true, CoordLocal = p0 + t1 * p1, Data = f1 };
      return true;
    }
    insideBefore = true;
    if (t2 > 0.0 && t2 * t2 * len2 > Intersection.RAY_EPSILON2)
    {
      hit = new SolidRecord { T = t2, Enter = false, Front = false, CoordLocal = p0 + t2 * p1, Data = f2 };
      return true;
    }
    insideBefore = false;
    return false;
  }

  // The boxed face index is allocated only for the winning hit.
  public void InitIntersection(in SolidRecord hit, Intersection target)
  {
    target.T = hit.T;
    target.Enter = hit.Enter;
    target.Front = hit.Front;
    target.CoordLocal = hit.CoordLocal;
    target.SolidData = hit.Data;
  }

  public override void CompleteIntersection(Intersection inter)
  {
    int face = (int)inter.SolidData!;
    inter.NormalLocal = Normals[face];
    inter.Normal = Vector3d.TransformNormalInverse(Normals[face], inter.WorldToLocal);
    Vector3d c = inter.CoordLocal;
    inter.TextureCoord = face < 2 ? new Vector2d(c.Y, c.Z) : face < 4 ? new Vector2d(c.X, c.Z) : new Vector2d(c.X, c.Y);
  }

  public void GetBoundingBox(out Vector3d corner1, out Vector3d corner2)
  {
    corner1 = Vector3d.Zero;
    corner2 = Vector3d.One;
  }
}
