using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// A rectangle as seen from a point: the solid angle it subtends and a map from [0,1)² onto it that is uniform by
/// solid angle and continuous (strata stay strata). After Ureña, Fajardo and King, "An Area-Preserving
/// Parametrization for Spherical Rectangles" (EGSR 2013): in a frame along the edges, u chooses the x at which a
/// slice of equal solid angle starts (inverting the area of the spherical quadrilateral up to it), v the y along that
/// slice, uniform in the sine of its elevation.
/// </summary>
internal readonly struct SphericalRectangle
{
  readonly Vector3d ex, ey, ez;      // unit edge directions; ez towards the point's side, flipped so z0 ≤ 0
  readonly double x0, x1, y0, y1, z0;
  readonly double b0, b1, k;

  /// <summary>Solid angle of the rectangle from the point (0 when the point lies in its plane).</summary>
  public readonly double SolidAngle;

  /// <param name="p">The point it is seen from.</param>
  /// <param name="corner">A corner; <paramref name="edge1"/> and <paramref name="edge2"/> the perpendicular edges from it.</param>
  public SphericalRectangle(in Vector3d p, in Vector3d corner, in Vector3d edge1, in Vector3d edge2)
  {
    double a = edge1.Length, b = edge2.Length;
    ex = edge1 / a;
    ey = edge2 / b;
    ez = Vector3d.Cross(ex, ey);
    Vector3d d = corner - p;
    x0 = Vector3d.Dot(d, ex);
    y0 = Vector3d.Dot(d, ey);
    z0 = Vector3d.Dot(d, ez);
    if (z0 > 0.0)
    {
      z0 = -z0;
      ez = -ez;
    }
    x1 = x0 + a;
    y1 = y0 + b;
    b0 = b1 = k = 0.0;
    SolidAngle = 0.0;
    if (!(z0 < 0.0))
      return;

    // Unit normals of the four planes through the point and an edge (v00→v10, v10→v11, v11→v01, v01→v00).
    double z2 = z0 * z0;
    Vector3d n0 = new Vector3d(0.0, z0, -y0) / Math.Sqrt(z2 + y0 * y0);
    Vector3d n1 = new Vector3d(-z0, 0.0, x1) / Math.Sqrt(z2 + x1 * x1);
    Vector3d n2 = new Vector3d(0.0, -z0, y1) / Math.Sqrt(z2 + y1 * y1);
    Vector3d n3 = new Vector3d(z0, 0.0, -x0) / Math.Sqrt(z2 + x0 * x0);
    // The quadrilateral's inner angles; its area is their sum less 2π.
    double g0 = Math.Acos(Math.Clamp(-Vector3d.Dot(n0, n1), -1.0, 1.0));
    double g1 = Math.Acos(Math.Clamp(-Vector3d.Dot(n1, n2), -1.0, 1.0));
    double g2 = Math.Acos(Math.Clamp(-Vector3d.Dot(n2, n3), -1.0, 1.0));
    double g3 = Math.Acos(Math.Clamp(-Vector3d.Dot(n3, n0), -1.0, 1.0));
    b0 = n0.Z;
    b1 = n2.Z;
    k = 2.0 * Math.PI - g2 - g3;
    SolidAngle = Math.Max(0.0, g0 + g1 - k);
  }

  /// <summary>The vector from the point to the rectangle's point for (u, v) of [0,1)²; uniform by solid angle.</summary>
  public Vector3d Sample(double u, double v)
  {
    // x: the slice [x0, xu] holds the fraction u of the solid angle.
    double au = u * SolidAngle + k;
    (double sinAu, double cosAu) = Math.SinCos(au);
    double fu = (cosAu * b0 - b1) / sinAu;
    double cu = Math.Clamp((fu > 0.0 ? 1.0 : -1.0) / Math.Sqrt(fu * fu + b0 * b0), -1.0, 1.0);
    double xu = -(cu * z0) / Math.Sqrt(Math.Max(1e-300, 1.0 - cu * cu));
    xu = Math.Clamp(xu, x0, x1);
    // y: uniform in the sine of the elevation along the slice at xu.
    double dd = Math.Sqrt(xu * xu + z0 * z0);
    double h0 = y0 / Math.Sqrt(dd * dd + y0 * y0);
    double h1 = y1 / Math.Sqrt(dd * dd + y1 * y1);
    double hv = h0 + v * (h1 - h0), hv2 = hv * hv;
    double yv = hv2 < 1.0 - 1e-12 ? hv * dd / Math.Sqrt(1.0 - hv2) : y1;
    yv = Math.Clamp(yv, y0, y1);
    return xu * ex + yv * ey + z0 * ez;
  }
}
