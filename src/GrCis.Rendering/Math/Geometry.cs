using System;
using OpenTK.Mathematics;

namespace MathSupport;

/// <summary>Small geometric helpers shared by shading and solids.</summary>
public static class Geometry
{
  /// <summary>Mirror of <paramref name="input"/> about <paramref name="normal"/>: 2(n·i)n − i.</summary>
  public static void SpecularReflection(ref Vector3d normal, ref Vector3d input, out Vector3d output)
  {
    double k = Vector3d.Dot(normal, input);
    output = 2.0 * k * normal - input;
  }

  public static Vector3d SpecularReflection(Vector3d normal, Vector3d input)
  {
    SpecularReflection(ref normal, ref input, out Vector3d output);
    return output;
  }

  /// <summary>
  /// Refracted direction for a ray leaving along <paramref name="input"/> reversed (input points away
  /// from the surface, towards where the ray came from). <paramref name="n"/> is the relative index of the
  /// side opposite to the normal. Returns the zero vector on total internal reflection.
  /// </summary>
  public static Vector3d SpecularRefraction(Vector3d normal, double n, Vector3d input)
  {
    normal.Normalize();
    input.Normalize();
    double d = Vector3d.Dot(normal, input);
    if (d < 0.0)
    {
      d = -d;
      normal = -normal;
    }
    else
      n = 1.0 / n;

    double cos2 = 1.0 - n * n * (1.0 - d * d);
    if (cos2 <= 0.0)
      return Vector3d.Zero;

    d = n * d - Math.Sqrt(cos2);
    return normal * d - input * n;
  }

  /// <summary>x^e for a non-negative integer exponent by repeated squaring.</summary>
  public static double IntPow(double x, int e)
  {
    if (e < 0)
      return 1.0 / IntPow(x, -e);
    double result = 1.0;
    while (e > 0)
    {
      if ((e & 1) != 0)
        result *= x;
      x *= x;
      e >>= 1;
    }
    return result;
  }

  public static bool IsZero(double a) => Math.Abs(a) <= double.Epsilon;

  public static bool IsZeroFast(double a) => Math.Abs(a) <= 1.0e-12;

  /// <summary>Two unit vectors perpendicular to <paramref name="n"/> and to each other.</summary>
  public static void GetTangents(Vector3d n, out Vector3d u, out Vector3d v)
  {
    n = n.Normalized();
    Vector3d a = Math.Abs(n.X) < 0.9 ? Vector3d.UnitX : Vector3d.UnitY;
    u = Vector3d.Cross(n, a).Normalized();
    v = Vector3d.Cross(n, u);
  }
}
