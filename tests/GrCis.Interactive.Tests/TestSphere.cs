using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Interactive.Tests;

/// <summary>Unit sphere at the local origin (stand-in until the solids branch lands).</summary>
internal sealed class TestSphere : DefaultSceneNode, ISolid
{
  public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
  {
    double a = Vector3d.Dot(p1, p1), b = 2.0 * Vector3d.Dot(p0, p1), c = Vector3d.Dot(p0, p0) - 1.0;
    double disc = b * b - 4.0 * a * c;
    if (disc <= 0.0)
      return null;
    double q = -0.5 * (b + Math.CopySign(Math.Sqrt(disc), b));
    double t0 = q / a, t1 = c / q;
    if (t0 > t1)
      (t0, t1) = (t1, t0);
    var list = new LinkedList<Intersection>();
    list.AddLast(Hit(p0, p1, t0, true));
    list.AddLast(Hit(p0, p1, t1, false));
    return list;
  }

  Intersection Hit(Vector3d p0, Vector3d p1, double t, bool enter)
  {
    Vector3d p = p0 + t * p1;
    return new Intersection(this) { T = t, Enter = enter, Front = enter, CoordLocal = p, NormalLocal = p };
  }

  public override void CompleteIntersection(Intersection inter) =>
    inter.Normal = Vector3d.TransformNormalInverse(inter.NormalLocal, inter.WorldToLocal);

  public void GetBoundingBox(out Vector3d c1, out Vector3d c2)
  {
    c1 = new Vector3d(-1, -1, -1);
    c2 = new Vector3d(1, 1, 1);
  }
}
