using System;
using OpenTK.Mathematics;

namespace MathSupport;

/// <summary>Small geometric helpers shared by shading and solids.</summary>
public static partial class Geometry
{
  /// <summary>Mirror of <paramref name="input"/> about <paramref name="normal"/>: 2(n·i)n − i.</summary>
  [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
  public static void SpecularReflection(ref Vector3d normal, ref Vector3d input, out Vector3d output)
  {
    double k = Vector3d.Dot(normal, input);
    output = 2.0 * k * normal - input;
  }

  /// <summary>
  /// The mirror image of <paramref name="input"/> about <paramref name="normal"/> (a unit vector): 2 (n·i) n − i. With
  /// <paramref name="input"/> pointing from the surface towards the viewer, the result points along the mirrored ray.
  /// </summary>
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
    input.Normalize();
    return SpecularRefractionUnit(normal, n, input);
  }

  /// <summary>
  /// <see cref="SpecularRefraction"/> of an input already normalized by <see cref="Vector3d.Normalize()"/> (the same
  /// value: a caller that has it saves the square root and division).
  /// </summary>
  [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]   // no reload of a returned vector
  internal static Vector3d SpecularRefractionUnit(Vector3d normal, double n, Vector3d input)
  {
    normal.Normalize();
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
  [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
  public static double IntPow(double x, int e) => e < 0 ? 1.0 / PowerLoop(x, -e) : PowerLoop(x, e);

  // Square-and-multiply for e >= 0; not recursive, so the JIT may inline it into the Phong model.
  static double PowerLoop(double x, int e)
  {
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

  /// <summary>True when <paramref name="a"/> is zero or the smallest subnormal number in magnitude.</summary>
  public static bool IsZero(double a) => Math.Abs(a) <= double.Epsilon;

  /// <summary>True when |<paramref name="a"/>| ≤ 10⁻¹²: zero up to rounding errors of unit-sized values.</summary>
  public static bool IsZeroFast(double a) => Math.Abs(a) <= 1.0e-12;

  /// <summary>Two unit vectors perpendicular to <paramref name="n"/> and to each other.</summary>
  public static void GetTangents(Vector3d n, out Vector3d u, out Vector3d v)
  {
    n = n.Normalized();
    Vector3d a = Math.Abs(n.X) < 0.9 ? Vector3d.UnitX : Vector3d.UnitY;
    u = Vector3d.Cross(n, a).Normalized();
    v = Vector3d.Cross(n, u);
  }

  /// <summary>
  /// GrCis's tangents of a direction: <paramref name="tu"/> towards +z ("north"), <paramref name="tv"/>
  /// around the z axis ("east"); not normalised. Continuous over a sphere except at its poles.
  /// </summary>
  public static void GetTangents(ref Vector3d p, out Vector3d tu, out Vector3d tv)
  {
    if (IsZero(p.X) && IsZero(p.Y))
    {
      tu = p.Z >= 0.0 ? Vector3d.UnitX : -Vector3d.UnitX;
      tv = Vector3d.UnitY;
      return;
    }
    tu = new Vector3d(-p.Z * p.X, -p.Z * p.Y, p.X * p.X + p.Y * p.Y);
    tv = new Vector3d(p.Y, -p.X, 0.0);
  }

  /// <summary>
  /// Two axes perpendicular to <paramref name="p"/> and to each other, with
  /// <c>p × p1 = p2</c>: <paramref name="p1"/> swaps the two largest components of p (one negated).
  /// Not normalised.
  /// </summary>
  public static void GetAxes(ref Vector3d p, out Vector3d p1, out Vector3d p2)
  {
    double ax = Math.Abs(p.X), ay = Math.Abs(p.Y), az = Math.Abs(p.Z);
    if (ax >= az && ay >= az)
      p1 = new Vector3d(-p.Y, p.X, 0.0);
    else if (ax >= ay && az >= ay)
      p1 = new Vector3d(-p.Z, 0.0, p.X);
    else
      p1 = new Vector3d(0.0, -p.Z, p.Y);
    p2 = Vector3d.Cross(p, p1);
  }

  /// <summary>A colour array { X, Y, Z }.</summary>
  public static double[] ColorCreate(in Vector3d col) => new[] { col.X, col.Y, col.Z };

  /// <summary>Double-precision copies (null stays null).</summary>
  public static Vector4d[]? Vector4dArrayFrom(in Vector4[]? v4) => v4 == null ? null : Array.ConvertAll(v4, v => (Vector4d)v);

  /// <summary>Double-precision copies (null stays null).</summary>
  public static Vector3d[]? Vector3dArrayFrom(in Vector3[]? v3) => v3 == null ? null : Array.ConvertAll(v3, v => (Vector3d)v);

  /// <summary>
  /// Ray <c>p0 + t p1</c> against triangle (a, b, c), Möller–Trumbore: returns t, or
  /// <see cref="double.NegativeInfinity"/> when the ray's line misses the triangle (t may be negative:
  /// the hit lies behind the origin). <paramref name="uv"/>: barycentric weights of b and c.
  /// </summary>
  public static double RayTriangleIntersection(ref Vector3d p0, ref Vector3d p1, ref Vector3d a, ref Vector3d b, ref Vector3d c, out Vector2d uv)
  {
    uv = Vector2d.Zero;
    Vector3d e1 = b - a, e2 = c - a;
    Vector3d pvec = Vector3d.Cross(p1, e2);
    double det = Vector3d.Dot(e1, pvec);
    if (IsZero(det))
      return double.NegativeInfinity;
    double inv = 1.0 / det;
    Vector3d tvec = p0 - a;
    uv.X = Vector3d.Dot(tvec, pvec) * inv;
    if (uv.X < 0.0 || uv.X > 1.0)
      return double.NegativeInfinity;
    Vector3d qvec = Vector3d.Cross(tvec, e1);
    uv.Y = Vector3d.Dot(p1, qvec) * inv;
    if (uv.Y < 0.0 || uv.X + uv.Y > 1.0)
      return double.NegativeInfinity;
    return Vector3d.Dot(e2, qvec) * inv;
  }

  /// <summary><see cref="RayTriangleIntersection(ref Vector3d, ref Vector3d, ref Vector3d, ref Vector3d, ref Vector3d, out Vector2d)"/> for single-precision vertices.</summary>
  public static double RayTriangleIntersection(ref Vector3d p0, ref Vector3d p1, ref Vector3 a, ref Vector3 b, ref Vector3 c, out Vector2d uv)
  {
    Vector3d da = a, db = b, dc = c;
    return RayTriangleIntersection(ref p0, ref p1, ref da, ref db, ref dc, out uv);
  }
}
