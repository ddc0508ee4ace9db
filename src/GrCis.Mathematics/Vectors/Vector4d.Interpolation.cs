using System;

namespace OpenTK.Mathematics;

// OpenTK 4's additions to Vector4d: absolute value, component comparisons (to a Vector4b), interpolation by a
// vector of blends, spherical and exponential interpolation.
public partial struct Vector4d
{
  /// <summary>The absolute value of every component.</summary>
  public static Vector4d Abs(Vector4d vec) => new(Math.Abs(vec.X), Math.Abs(vec.Y), Math.Abs(vec.Z), Math.Abs(vec.W));
  /// <summary><see cref="Abs(Vector4d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Abs(in Vector4d vec, out Vector4d result) => result = Abs(vec);

  /// <summary>Per component, whether <paramref name="left"/>'s is less than <paramref name="right"/>'s.</summary>
  public static Vector4b LessThan(in Vector4d left, in Vector4d right) => new(
    left.X < right.X, left.Y < right.Y, left.Z < right.Z, left.W < right.W);
  /// <summary>Per component, whether <paramref name="left"/>'s is less than or equal to
  /// <paramref name="right"/>'s.</summary>
  public static Vector4b LessThanOrEqual(in Vector4d left, in Vector4d right) => new(
    left.X <= right.X, left.Y <= right.Y, left.Z <= right.Z, left.W <= right.W);
  /// <summary>Per component, whether <paramref name="left"/>'s is greater than <paramref name="right"/>'s.</summary>
  public static Vector4b GreaterThan(in Vector4d left, in Vector4d right) => new(
    left.X > right.X, left.Y > right.Y, left.Z > right.Z, left.W > right.W);
  /// <summary>Per component, whether <paramref name="left"/>'s is greater than or equal to
  /// <paramref name="right"/>'s.</summary>
  public static Vector4b GreaterThanOrEqual(in Vector4d left, in Vector4d right) => new(
    left.X >= right.X, left.Y >= right.Y, left.Z >= right.Z, left.W >= right.W);

  /// <summary>Each component blended by its own weight: <c>a + blend · (b − a)</c>.</summary>
  public static Vector4d Lerp(Vector4d a, Vector4d b, Vector4d blend) => new(
    blend.X * (b.X - a.X) + a.X, blend.Y * (b.Y - a.Y) + a.Y, blend.Z * (b.Z - a.Z) + a.Z, blend.W * (b.W - a.W) + a.W);
  /// <summary><see cref="Lerp(Vector4d, Vector4d, Vector4d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Lerp(in Vector4d a, in Vector4d b, Vector4d blend, out Vector4d result) => result = Lerp(a, b, blend);

  /// <summary>
  /// Interpolates along the arc between the directions of <paramref name="a"/> and <paramref name="b"/> (their
  /// lengths weighted as the directions); falls back to <see cref="Lerp(Vector4d, Vector4d, double)"/> when either is zero or
  /// they are nearly parallel (|cos θ| > 0.9999), where the arc is ill-defined.
  /// </summary>
  public static Vector4d Slerp(Vector4d a, Vector4d b, double t)
  {
    double lengths = a.Length * b.Length;
    if (lengths == 0) return Lerp(a, b, t);
    double cos = Dot(a, b) / lengths;
    if (Math.Abs(cos) > 0.9999) return Lerp(a, b, t);
    double theta = Math.Acos(Math.Clamp(cos, -1, 1));
    double sin = Math.Sqrt(1 - cos * cos);
    return Math.Sin((1 - t) * theta) / sin * a + Math.Sin(t * theta) / sin * b;
  }

  /// <summary><see cref="Slerp(Vector4d, Vector4d, double)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Slerp(in Vector4d a, in Vector4d b, double t, out Vector4d result) => result = Slerp(a, b, t);

  /// <summary>Exponential interpolation, per component <c>a^(1 − t) · b^t</c> (for positive components).</summary>
  public static Vector4d Elerp(Vector4d a, Vector4d b, double t) => new(
    Math.Pow(a.X, 1 - t) * Math.Pow(b.X, t), Math.Pow(a.Y, 1 - t) * Math.Pow(b.Y, t), Math.Pow(a.Z, 1 - t) * Math.Pow(b.Z, t), Math.Pow(a.W, 1 - t) * Math.Pow(b.W, t));
  /// <summary><see cref="Elerp(Vector4d, Vector4d, double)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Elerp(in Vector4d a, in Vector4d b, double t, out Vector4d result) => result = Elerp(a, b, t);
}
