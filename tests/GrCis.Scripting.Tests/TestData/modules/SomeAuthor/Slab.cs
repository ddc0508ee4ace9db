using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;

namespace SomeAuthor
{
  /// <summary>The infinite slab -Thickness/2 &lt;= z &lt;= Thickness/2 in local space.</summary>
  public class Slab : DefaultSceneNode, ISolid
  {
    public double Thickness;

    public Slab(double thickness = 1.0)
    {
      Thickness = thickness;
    }

    public override LinkedList<Intersection> Intersect(Vector3d p0, Vector3d p1)
    {
      if (Math.Abs(p1.Z) < 1.0e-12)
        return null;
      double h = 0.5 * Thickness;
      double t1 = (-h - p0.Z) / p1.Z;
      double t2 = (h - p0.Z) / p1.Z;
      if (t1 > t2)
      {
        double tmp = t1;
        t1 = t2;
        t2 = tmp;
      }

      var result = new LinkedList<Intersection>();
      result.AddLast(Hit(p0, p1, t1, true));
      result.AddLast(Hit(p0, p1, t2, false));
      return result;
    }

    Intersection Hit(Vector3d p0, Vector3d p1, double t, bool enter)
    {
      var i = new Intersection(this);
      i.T = t;
      i.Enter = enter;
      i.Front = enter;
      i.CoordLocal = p0 + t * p1;
      return i;
    }

    public void GetBoundingBox(out Vector3d corner1, out Vector3d corner2)
    {
      double h = 0.5 * Thickness;
      corner1 = new Vector3d(-INFINITY, -INFINITY, -h);
      corner2 = new Vector3d(INFINITY, INFINITY, h);
    }

    const double INFINITY = 1.0e6;
  }
}
