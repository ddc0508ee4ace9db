using System;

namespace OpenTK.Mathematics;

// OpenTK 4's additions to Vector2d: absolute value, component comparisons (to a Vector2b), interpolation by a
// vector of blends, spherical and exponential interpolation.
public partial struct Vector2d
{
  /// <summary>The absolute value of every component.</summary>
  public static Vector2d Abs(Vector2d vec) => new(Math.Abs(vec.X), Math.Abs(vec.Y));
  /// <summary><see cref="Abs(Vector2d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Abs(in Vector2d vec, out Vector2d result) => result = Abs(vec);

  /// <summary>Per component, whether <paramref name="left"/>'s is less than <paramref name="right"/>'s.</summary>
  public static Vector2b LessThan(in Vector2d left, in Vector2d right) => new(left.X < right.X, left.Y < right.Y);
  /// <summary>Per component, whether <paramref name="left"/>'s is less than or equal to
  /// <paramref name="right"/>'s.</summary>
  public static Vector2b LessThanOrEqual(in Vector2d left, in Vector2d right) => new(left.X <= right.X, left.Y <= right.Y);
  /// <summary>Per component, whether <paramref name="left"/>'s is greater than <paramref name="right"/>'s.</summary>
  public static Vector2b GreaterThan(in Vector2d left, in Vector2d right) => new(left.X > right.X, left.Y > right.Y);
  /// <summary>Per component, whether <paramref name="left"/>'s is greater than or equal to
  /// <paramref name="right"/>'s.</summary>
  public static Vector2b GreaterThanOrEqual(in Vector2d left, in Vector2d right) => new(left.X >= right.X, left.Y >= right.Y);

  /// <summary>Each component blended by its own weight: <c>a + blend · (b − a)</c>.</summary>
  public static Vector2d Lerp(Vector2d a, Vector2d b, Vector2d blend) => new(
    blend.X * (b.X - a.X) + a.X, blend.Y * (b.Y - a.Y) + a.Y);
  /// <summary><see cref="Lerp(Vector2d, Vector2d, Vector2d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Lerp(in Vector2d a, in Vector2d b, Vector2d blend, out Vector2d result) => result = Lerp(a, b, blend);

  /// <summary>
  /// Interpolates along the arc between the directions of <paramref name="a"/> and <paramref name="b"/> (their
  /// lengths weighted as the directions); falls back to <see cref="Lerp(Vector2d, Vector2d, double)"/> when either is zero or
  /// they are nearly parallel (|cos θ| > 0.9999), where the arc is ill-defined.
  /// </summary>
  public static Vector2d Slerp(Vector2d a, Vector2d b, double t)
  {
    double lengths = a.Length * b.Length;
    if (lengths == 0) return Lerp(a, b, t);
    double cos = Dot(a, b) / lengths;
    if (Math.Abs(cos) > 0.9999) return Lerp(a, b, t);
    double theta = Math.Acos(Math.Clamp(cos, -1, 1));
    double sin = Math.Sqrt(1 - cos * cos);
    return Math.Sin((1 - t) * theta) / sin * a + Math.Sin(t * theta) / sin * b;
  }

  /// <summary><see cref="Slerp(Vector2d, Vector2d, double)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Slerp(in Vector2d a, in Vector2d b, double t, out Vector2d result) => result = Slerp(a, b, t);

  /// <summary>Exponential interpolation, per component <c>a^(1 − t) · b^t</c> (for positive components).</summary>
  public static Vector2d Elerp(Vector2d a, Vector2d b, double t) => new(
    Math.Pow(a.X, 1 - t) * Math.Pow(b.X, t), Math.Pow(a.Y, 1 - t) * Math.Pow(b.Y, t));
  /// <summary><see cref="Elerp(Vector2d, Vector2d, double)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Elerp(in Vector2d a, in Vector2d b, double t, out Vector2d result) => result = Elerp(a, b, t);
}
