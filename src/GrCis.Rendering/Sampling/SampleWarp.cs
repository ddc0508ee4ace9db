using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// Maps uniform points of [0,1)² to the shapes and lobes that rendering samples (a lens disk, a cone of
/// directions towards a sphere, the cosine and Phong lobes), keeping stratification (each map is continuous).
/// </summary>
public static class SampleWarp
{
  /// <summary>A point of the unit disk, uniform by area (Shirley–Chiu's concentric map: strata stay compact).</summary>
  public static Vector2d ConcentricDisk(double u, double v)
  {
    double a = 2.0 * u - 1.0, b = 2.0 * v - 1.0;
    if (a == 0.0 && b == 0.0)
      return Vector2d.Zero;
    double r, phi;
    if (Math.Abs(a) > Math.Abs(b))
    {
      r = a;
      phi = Math.PI / 4.0 * (b / a);
    }
    else
    {
      r = b;
      phi = Math.PI / 2.0 - Math.PI / 4.0 * (a / b);
    }
    return new Vector2d(r * Math.Cos(phi), r * Math.Sin(phi));
  }

  /// <summary>
  /// A direction around the unit <paramref name="axis"/> with density cos^<paramref name="exponent"/>(angle)·(e+1)/(2π)
  /// per steradian (0 = uniform over the hemisphere, 1 = cosine-weighted).
  /// </summary>
  public static Vector3d PowerCosine(double u, double v, in Vector3d axis, double exponent)
  {
    return AroundAxis(Math.Pow(1.0 - u, 1.0 / (exponent + 1.0)), v, axis);
  }

  /// <summary><see cref="PowerCosine"/> with exponent 1 (the Lambertian lobe): a square root where the general lobe needs a power.</summary>
  public static Vector3d CosineHemisphere(double u, double v, in Vector3d axis) => AroundAxis(Math.Sqrt(1.0 - u), v, axis);

  /// <summary>Density of <see cref="PowerCosine"/> for a direction at cosine <paramref name="cos"/> from the axis.</summary>
  public static double PowerCosinePdf(double cos, double exponent) =>
    cos <= 0.0 ? 0.0 : (exponent + 1.0) / (2.0 * Math.PI) * Math.Pow(cos, exponent);

  /// <summary>A direction inside the cone around the unit <paramref name="axis"/> with cosine ≥ <paramref name="cosMax"/>, uniform by solid angle.</summary>
  public static Vector3d UniformCone(double u, double v, in Vector3d axis, double cosMax)
  {
    return AroundAxis(1.0 - u * (1.0 - cosMax), v, axis);
  }

  /// <summary>The unit direction at cosine <paramref name="cos"/> from <paramref name="axis"/>, turned by 2π·<paramref name="v"/> about it.</summary>
  static Vector3d AroundAxis(double cos, double v, in Vector3d axis)
  {
    double sin = Math.Sqrt(Math.Max(0.0, 1.0 - cos * cos));
    (double sinPhi, double cosPhi) = Math.SinCos(2.0 * Math.PI * v);
    Frame(axis, out Vector3d t, out Vector3d b);
    return t * (sin * cosPhi) + b * (sin * sinPhi) + axis * cos;
  }

  /// <summary>Two unit vectors completing the unit <paramref name="n"/> to an orthonormal frame (Duff et al. 2017, no branch on a threshold).</summary>
  public static void Frame(in Vector3d n, out Vector3d t, out Vector3d b)
  {
    double sign = n.Z >= 0.0 ? 1.0 : -1.0;
    double a = -1.0 / (sign + n.Z);
    double c = n.X * n.Y * a;
    t = new Vector3d(1.0 + sign * n.X * n.X * a, sign * c, -sign * n.X);
    b = new Vector3d(c, sign + n.Y * n.Y * a, -n.Y);
  }
}
