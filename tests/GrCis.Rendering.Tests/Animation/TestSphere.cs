using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Animation;

/// <summary>Unit sphere at the local origin (the solids branch owns the real one).</summary>
internal sealed class TestSphere : DefaultSceneNode, ISolid
{
  public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
  {
    double a = Vector3d.Dot(p1, p1), b = Vector3d.Dot(p0, p1), c = Vector3d.Dot(p0, p0) - 1.0;
    double d = b * b - a * c;
    if (d <= 0.0)
      return null;
    double s = System.Math.Sqrt(d);
    double t1 = (-b - s) / a, t2 = (-b + s) / a;
    var list = new LinkedList<Intersection>();
    list.AddLast(new Intersection(this) { T = t1, Enter = true, Front = true, CoordLocal = p0 + t1 * p1 });
    list.AddLast(new Intersection(this) { T = t2, Enter = false, Front = false, CoordLocal = p0 + t2 * p1 });
    return list;
  }

  public override void CompleteIntersection(Intersection inter) =>
    inter.Normal = Vector3d.TransformNormalInverse(inter.CoordLocal, inter.WorldToLocal);

  public void GetBoundingBox(out Vector3d c1, out Vector3d c2)
  {
    c1 = -Vector3d.One;
    c2 = Vector3d.One;
  }
}
