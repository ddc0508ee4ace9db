using System;

namespace OpenTK.Mathematics;

// OpenTK 4's additions to Vector4: absolute value, component comparisons (to a Vector4b), interpolation by a
// vector of blends, spherical and exponential interpolation.
public partial struct Vector4
{
  /// <summary>The absolute value of every component.</summary>
  public static Vector4 Abs(Vector4 vec) => new(MathF.Abs(vec.X), MathF.Abs(vec.Y), MathF.Abs(vec.Z), MathF.Abs(vec.W));
  /// <summary><see cref="Abs(Vector4)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Abs(in Vector4 vec, out Vector4 result) => result = Abs(vec);

  /// <summary>Per component, whether <paramref name="left"/>'s is less than <paramref name="right"/>'s.</summary>
  public static Vector4b LessThan(in Vector4 left, in Vector4 right) => new(
    left.X < right.X, left.Y < right.Y, left.Z < right.Z, left.W < right.W);
  /// <summary>Per component, whether <paramref name="left"/>'s is less than or equal to
  /// <paramref name="right"/>'s.</summary>
  public static Vector4b LessThanOrEqual(in Vector4 left, in Vector4 right) => new(
    left.X <= right.X, left.Y <= right.Y, left.Z <= right.Z, left.W <= right.W);
  /// <summary>Per component, whether <paramref name="left"/>'s is greater than <paramref name="right"/>'s.</summary>
  public static Vector4b GreaterThan(in Vector4 left, in Vector4 right) => new(
    left.X > right.X, left.Y > right.Y, left.Z > right.Z, left.W > right.W);
  /// <summary>Per component, whether <paramref name="left"/>'s is greater than or equal to
  /// <paramref name="right"/>'s.</summary>
  public static Vector4b GreaterThanOrEqual(in Vector4 left, in Vector4 right) => new(
    left.X >= right.X, left.Y >= right.Y, left.Z >= right.Z, left.W >= right.W);

  /// <summary>Each component blended by its own weight: <c>a + blend · (b − a)</c>.</summary>
  public static Vector4 Lerp(Vector4 a, Vector4 b, Vector4 blend) => new(
    blend.X * (b.X - a.X) + a.X, blend.Y * (b.Y - a.Y) + a.Y, blend.Z * (b.Z - a.Z) + a.Z, blend.W * (b.W - a.W) + a.W);
  /// <summary><see cref="Lerp(Vector4, Vector4, Vector4)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Lerp(in Vector4 a, in Vector4 b, Vector4 blend, out Vector4 result) => result = Lerp(a, b, blend);

  /// <summary>
  /// Interpolates along the arc between the directions of <paramref name="a"/> and <paramref name="b"/> (their
  /// lengths weighted as the directions); falls back to <see cref="Lerp(Vector4, Vector4, float)"/> when either is zero or
  /// they are nearly parallel (|cos θ| > 0.9999), where the arc is ill-defined.
  /// </summary>
  public static Vector4 Slerp(Vector4 a, Vector4 b, float t)
  {
    float lengths = a.Length * b.Length;
    if (lengths == 0) return Lerp(a, b, t);
    float cos = Dot(a, b) / lengths;
    if (MathF.Abs(cos) > 0.9999f) return Lerp(a, b, t);
    float theta = MathF.Acos(Math.Clamp(cos, -1, 1));
    float sin = MathF.Sqrt(1 - cos * cos);
    return MathF.Sin((1 - t) * theta) / sin * a + MathF.Sin(t * theta) / sin * b;
  }

  /// <summary><see cref="Slerp(Vector4, Vector4, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Slerp(in Vector4 a, in Vector4 b, float t, out Vector4 result) => result = Slerp(a, b, t);

  /// <summary>Exponential interpolation, per component <c>a^(1 − t) · b^t</c> (for positive components).</summary>
  public static Vector4 Elerp(Vector4 a, Vector4 b, float t) => new(
    MathF.Pow(a.X, 1 - t) * MathF.Pow(b.X, t), MathF.Pow(a.Y, 1 - t) * MathF.Pow(b.Y, t), MathF.Pow(a.Z, 1 - t) * MathF.Pow(b.Z, t), MathF.Pow(a.W, 1 - t) * MathF.Pow(b.W, t));
  /// <summary><see cref="Elerp(Vector4, Vector4, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Elerp(in Vector4 a, in Vector4 b, float t, out Vector4 result) => result = Elerp(a, b, t);
}
