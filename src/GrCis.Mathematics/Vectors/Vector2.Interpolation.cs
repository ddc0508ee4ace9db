using System;

namespace OpenTK.Mathematics;

// OpenTK 4's additions to Vector2: absolute value, component comparisons (to a Vector2b), interpolation by a
// vector of blends, spherical and exponential interpolation.
public partial struct Vector2
{
  /// <summary>The absolute value of every component.</summary>
  public static Vector2 Abs(Vector2 vec) => new(MathF.Abs(vec.X), MathF.Abs(vec.Y));
  /// <summary><see cref="Abs(Vector2)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Abs(in Vector2 vec, out Vector2 result) => result = Abs(vec);

  /// <summary>Per component, whether <paramref name="left"/>'s is less than <paramref name="right"/>'s.</summary>
  public static Vector2b LessThan(in Vector2 left, in Vector2 right) => new(left.X < right.X, left.Y < right.Y);
  /// <summary>Per component, whether <paramref name="left"/>'s is less than or equal to
  /// <paramref name="right"/>'s.</summary>
  public static Vector2b LessThanOrEqual(in Vector2 left, in Vector2 right) => new(left.X <= right.X, left.Y <= right.Y);
  /// <summary>Per component, whether <paramref name="left"/>'s is greater than <paramref name="right"/>'s.</summary>
  public static Vector2b GreaterThan(in Vector2 left, in Vector2 right) => new(left.X > right.X, left.Y > right.Y);
  /// <summary>Per component, whether <paramref name="left"/>'s is greater than or equal to
  /// <paramref name="right"/>'s.</summary>
  public static Vector2b GreaterThanOrEqual(in Vector2 left, in Vector2 right) => new(left.X >= right.X, left.Y >= right.Y);

  /// <summary>Each component blended by its own weight: <c>a + blend · (b − a)</c>.</summary>
  public static Vector2 Lerp(Vector2 a, Vector2 b, Vector2 blend) => new(
    blend.X * (b.X - a.X) + a.X, blend.Y * (b.Y - a.Y) + a.Y);
  /// <summary><see cref="Lerp(Vector2, Vector2, Vector2)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Lerp(in Vector2 a, in Vector2 b, Vector2 blend, out Vector2 result) => result = Lerp(a, b, blend);

  /// <summary>
  /// Interpolates along the arc between the directions of <paramref name="a"/> and <paramref name="b"/> (their
  /// lengths weighted as the directions); falls back to <see cref="Lerp(Vector2, Vector2, float)"/> when either is zero or
  /// they are nearly parallel (|cos θ| > 0.9999), where the arc is ill-defined.
  /// </summary>
  public static Vector2 Slerp(Vector2 a, Vector2 b, float t)
  {
    float lengths = a.Length * b.Length;
    if (lengths == 0) return Lerp(a, b, t);
    float cos = Dot(a, b) / lengths;
    if (MathF.Abs(cos) > 0.9999f) return Lerp(a, b, t);
    float theta = MathF.Acos(Math.Clamp(cos, -1, 1));
    float sin = MathF.Sqrt(1 - cos * cos);
    return MathF.Sin((1 - t) * theta) / sin * a + MathF.Sin(t * theta) / sin * b;
  }

  /// <summary><see cref="Slerp(Vector2, Vector2, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Slerp(in Vector2 a, in Vector2 b, float t, out Vector2 result) => result = Slerp(a, b, t);

  /// <summary>Exponential interpolation, per component <c>a^(1 − t) · b^t</c> (for positive components).</summary>
  public static Vector2 Elerp(Vector2 a, Vector2 b, float t) => new(
    MathF.Pow(a.X, 1 - t) * MathF.Pow(b.X, t), MathF.Pow(a.Y, 1 - t) * MathF.Pow(b.Y, t));
  /// <summary><see cref="Elerp(Vector2, Vector2, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Elerp(in Vector2 a, in Vector2 b, float t, out Vector2 result) => result = Elerp(a, b, t);
}
