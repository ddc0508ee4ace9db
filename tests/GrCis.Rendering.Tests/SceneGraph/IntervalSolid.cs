using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.SceneGraph;

/// <summary>Test solid: the slab a ≤ x ≤ b, so CSG results are easy to predict along the x axis.</summary>
internal sealed class IntervalSolid : DefaultSceneNode, ISolid
{
  readonly double a, b;

  public IntervalSolid(double a, double b)
  {
    this.a = a;
    this.b = b;
  }

  public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
  {
    if (p1.X == 0.0)
      return null;
    double ta = (a - p0.X) / p1.X, tb = (b - p0.X) / p1.X;
    bool forward = p1.X > 0;
    var list = new LinkedList<Intersection>();
    double t1 = System.Math.Min(ta, tb), t2 = System.Math.Max(ta, tb);
    list.AddLast(new Intersection(this) { T = t1, Enter = true, Front = true, CoordLocal = p0 + t1 * p1, NormalLocal = new Vector3d(forward ? -1 : 1, 0, 0) });
    list.AddLast(new Intersection(this) { T = t2, Enter = false, Front = false, CoordLocal = p0 + t2 * p1, NormalLocal = new Vector3d(forward ? 1 : -1, 0, 0) });
    return list;
  }

  public override void CompleteIntersection(Intersection inter) =>
    inter.Normal = Vector3d.TransformNormalInverse(inter.NormalLocal, inter.WorldToLocal);

  public void GetBoundingBox(out Vector3d c1, out Vector3d c2)
  {
    c1 = new Vector3d(a, double.NegativeInfinity, double.NegativeInfinity);
    c2 = new Vector3d(b, double.PositiveInfinity, double.PositiveInfinity);
  }
}
