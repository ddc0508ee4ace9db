using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>A sphere of radius r about the local origin as a bounding volume.</summary>
public class BoundingSphere : IBoundingVolume
{
  readonly double rr;

  /// <summary>A bounding sphere about the local origin.</summary>
  /// <param name="r">Radius in local units (default 1).</param>
  public BoundingSphere(double r = 1.0) => rr = r * r;

  /// <inheritdoc/>
  public double Intersect(Vector3d p0, Vector3d p1)
  {
    double od = Vector3d.Dot(p0, p1);
    double dd = Vector3d.Dot(p1, p1);
    double oo = Vector3d.Dot(p0, p0);
    // Quarter discriminant of |p0 + t p1|² = r²: no real root, no hit (a touch counts as a miss).
    double disc = od * od + dd * (rr - oo);
    if (disc <= 0.0)
      return -1.0;
    double root = Math.Sqrt(disc);
    if (root - od < 0.0)        // the far root is behind the origin
      return -1.0;
    if (root + od >= 0.0)       // the near root is not ahead: the origin is inside
      return 0.0;
    return -(root + od) / dd;
  }
}
