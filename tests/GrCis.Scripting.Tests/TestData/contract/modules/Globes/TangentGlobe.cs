using System;
using System.Collections.Generic;
using OpenTK;
using Rendering;

namespace Globes
{
  /// <summary>Unit sphere of a student's module: completion fills only the local tangents (east, north).</summary>
  public class TangentGlobe : DefaultSceneNode, ISolid
  {
    public override LinkedList<Intersection> Intersect(Vector3d p0, Vector3d p1)
    {
      double OD = Vector3d.Dot(p0, p1);
      double DD = Vector3d.Dot(p1, p1);
      double d = OD * OD + DD * (1.0 - Vector3d.Dot(p0, p0));
      if (d <= 0.0)
        return null;

      d = Math.Sqrt(d);
      var result = new LinkedList<Intersection>();
      double t = (-OD - d) / DD;
      result.AddLast(new Intersection(this) { T = t, Enter = true, Front = true, CoordLocal = p0 + t * p1 });
      t = (-OD + d) / DD;
      result.AddLast(new Intersection(this) { T = t, Enter = false, Front = false, CoordLocal = p0 + t * p1 });
      return result;
    }

    public override void CompleteIntersection(Intersection inter)
    {
      Vector3d p = inter.CoordLocal;
      double r2 = p.X * p.X + p.Y * p.Y;
      if (r2 < 1.0e-20)
      {
        inter.TangentU = Vector3d.UnitX;
        inter.TangentV = p.Z >= 0.0 ? Vector3d.UnitY : -Vector3d.UnitY;
        return;
      }
      inter.TangentU = new Vector3d(-p.Y, p.X, 0.0);
      inter.TangentV = new Vector3d(-p.Z * p.X, -p.Z * p.Y, r2);
    }

    public void GetBoundingBox(out Vector3d corner1, out Vector3d corner2)
    {
      corner1 = new Vector3d(-1.0, -1.0, -1.0);
      corner2 = new Vector3d(1.0, 1.0, 1.0);
    }
  }
}
