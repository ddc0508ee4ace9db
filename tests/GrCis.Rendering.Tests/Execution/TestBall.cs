using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Execution;

/// <summary>Test solid: sphere of radius <see cref="Radius"/> at the local origin (independent of the Solids folder).</summary>
internal sealed class TestBall : DefaultSceneNode, ISolid
{
  public double Radius = 1.0;

  public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
  {
    // Numerically stable quadratic for |p0 + t p1|² = r².
    double a = Vector3d.Dot(p1, p1);
    double b = 2.0 * Vector3d.Dot(p0, p1);
    double c = Vector3d.Dot(p0, p0) - Radius * Radius;
    double disc = b * b - 4.0 * a * c;
    if (disc <= 0.0 || a == 0.0)
      return null;
    double q = -0.5 * (b + System.Math.CopySign(System.Math.Sqrt(disc), b));
    double t0 = q / a, t1 = c / q;
    if (t0 > t1)
      (t0, t1) = (t1, t0);
    var list = new LinkedList<Intersection>();
    list.AddLast(Hit(p0, p1, t0, enter: true));
    list.AddLast(Hit(p0, p1, t1, enter: false));
    return list;
  }

  Intersection Hit(Vector3d p0, Vector3d p1, double t, bool enter)
  {
    Vector3d local = p0 + t * p1;
    return new Intersection(this) { T = t, Enter = enter, Front = enter, CoordLocal = local, NormalLocal = local };
  }

  public override void CompleteIntersection(Intersection inter)
  {
    inter.Normal = Vector3d.TransformNormalInverse(inter.NormalLocal, inter.WorldToLocal).Normalized();
    inter.TextureCoord = new Vector2d(System.Math.Atan2(inter.CoordLocal.Z, inter.CoordLocal.X), inter.CoordLocal.Y);
  }

  public void GetBoundingBox(out Vector3d c1, out Vector3d c2)
  {
    c1 = new Vector3d(-Radius);
    c2 = new Vector3d(Radius);
  }
}
