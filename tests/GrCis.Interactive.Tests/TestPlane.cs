using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Interactive.Tests;

/// <summary>The infinite plane z = 0 in local space, normal facing the ray (stand-in until the solids branch lands).</summary>
internal sealed class TestPlane : DefaultSceneNode, ISolid
{
  public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
  {
    // Rays (nearly) parallel to the plane miss it rather than hit at a huge distance.
    if (System.Math.Abs(p1.Z) < 1e-12 * p1.Length)
      return null;
    double t = -p0.Z / p1.Z;
    if (t <= 0.0)
      return null;
    bool front = p1.Z < 0.0;
    var list = new LinkedList<Intersection>();
    list.AddLast(new Intersection(this)
    {
      T = t,
      Enter = front,
      Front = front,
      CoordLocal = p0 + t * p1,
      NormalLocal = front ? Vector3d.UnitZ : -Vector3d.UnitZ,
    });
    return list;
  }

  public override void CompleteIntersection(Intersection inter) =>
    inter.Normal = Vector3d.TransformNormalInverse(inter.NormalLocal, inter.WorldToLocal);

  public void GetBoundingBox(out Vector3d c1, out Vector3d c2)
  {
    c1 = new Vector3d(double.NegativeInfinity, double.NegativeInfinity, 0);
    c2 = new Vector3d(double.PositiveInfinity, double.PositiveInfinity, 0);
  }
}
