using System;

namespace OpenTK.Mathematics;

// OpenTK 4's additions to Vector3: absolute value, component comparisons (to a Vector3b), interpolation by a
// vector of blends, spherical and exponential interpolation.
public partial struct Vector3
{
  /// <summary>The absolute value of every component.</summary>
  public static Vector3 Abs(Vector3 vec) => new(MathF.Abs(vec.X), MathF.Abs(vec.Y), MathF.Abs(vec.Z));
  /// <summary><see cref="Abs(Vector3)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Abs(in Vector3 vec, out Vector3 result) => result = Abs(vec);

  /// <summary>Per component, whether <paramref name="left"/>'s is less than <paramref name="right"/>'s.</summary>
  public static Vector3b LessThan(in Vector3 left, in Vector3 right) => new(left.X < right.X, left.Y < right.Y, left.Z < right.Z);
  /// <summary>Per component, whether <paramref name="left"/>'s is less than or equal to
  /// <paramref name="right"/>'s.</summary>
  public static Vector3b LessThanOrEqual(in Vector3 left, in Vector3 right) => new(
    left.X <= right.X, left.Y <= right.Y, left.Z <= right.Z);
  /// <summary>Per component, whether <paramref name="left"/>'s is greater than <paramref name="right"/>'s.</summary>
  public static Vector3b GreaterThan(in Vector3 left, in Vector3 right) => new(
    left.X > right.X, left.Y > right.Y, left.Z > right.Z);
  /// <summary>Per component, whether <paramref name="left"/>'s is greater than or equal to
  /// <paramref name="right"/>'s.</summary>
  public static Vector3b GreaterThanOrEqual(in Vector3 left, in Vector3 right) => new(
    left.X >= right.X, left.Y >= right.Y, left.Z >= right.Z);

  /// <summary>Each component blended by its own weight: <c>a + blend · (b − a)</c>.</summary>
  public static Vector3 Lerp(Vector3 a, Vector3 b, Vector3 blend) => new(
    blend.X * (b.X - a.X) + a.X, blend.Y * (b.Y - a.Y) + a.Y, blend.Z * (b.Z - a.Z) + a.Z);
  /// <summary><see cref="Lerp(Vector3, Vector3, Vector3)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Lerp(in Vector3 a, in Vector3 b, Vector3 blend, out Vector3 result) => result = Lerp(a, b, blend);

  /// <summary>
  /// Interpolates along the arc between the directions of <paramref name="a"/> and <paramref name="b"/> (their
  /// lengths weighted as the directions); falls back to <see cref="Lerp(Vector3, Vector3, float)"/> when either is zero or
  /// they are nearly parallel (|cos θ| > 0.9999), where the arc is ill-defined.
  /// </summary>
  public static Vector3 Slerp(Vector3 a, Vector3 b, float t)
  {
    float lengths = a.Length * b.Length;
    if (lengths == 0) return Lerp(a, b, t);
    float cos = Dot(a, b) / lengths;
    if (MathF.Abs(cos) > 0.9999f) return Lerp(a, b, t);
    float theta = MathF.Acos(Math.Clamp(cos, -1, 1));
    float sin = MathF.Sqrt(1 - cos * cos);
    return MathF.Sin((1 - t) * theta) / sin * a + MathF.Sin(t * theta) / sin * b;
  }

  /// <summary><see cref="Slerp(Vector3, Vector3, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Slerp(in Vector3 a, in Vector3 b, float t, out Vector3 result) => result = Slerp(a, b, t);

  /// <summary>Exponential interpolation, per component <c>a^(1 − t) · b^t</c> (for positive components).</summary>
  public static Vector3 Elerp(Vector3 a, Vector3 b, float t) => new(
    MathF.Pow(a.X, 1 - t) * MathF.Pow(b.X, t), MathF.Pow(a.Y, 1 - t) * MathF.Pow(b.Y, t), MathF.Pow(a.Z, 1 - t) * MathF.Pow(b.Z, t));
  /// <summary><see cref="Elerp(Vector3, Vector3, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Elerp(in Vector3 a, in Vector3 b, float t, out Vector3 result) => result = Elerp(a, b, t);
}
