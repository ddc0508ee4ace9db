using System;

namespace OpenTK.Mathematics;

// OpenTK 4's additions to Vector3d: absolute value, component comparisons (to a Vector3b), interpolation by a
// vector of blends, spherical and exponential interpolation.
public partial struct Vector3d
{
  /// <summary><see cref="Abs(Vector3d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Abs(in Vector3d vec, out Vector3d result) => result = Abs(vec);

  /// <summary>Per component, whether <paramref name="left"/>'s is less than <paramref name="right"/>'s.</summary>
  public static Vector3b LessThan(in Vector3d left, in Vector3d right) => new(
    left.X < right.X, left.Y < right.Y, left.Z < right.Z);
  /// <summary>Per component, whether <paramref name="left"/>'s is less than or equal to
  /// <paramref name="right"/>'s.</summary>
  public static Vector3b LessThanOrEqual(in Vector3d left, in Vector3d right) => new(
    left.X <= right.X, left.Y <= right.Y, left.Z <= right.Z);
  /// <summary>Per component, whether <paramref name="left"/>'s is greater than <paramref name="right"/>'s.</summary>
  public static Vector3b GreaterThan(in Vector3d left, in Vector3d right) => new(
    left.X > right.X, left.Y > right.Y, left.Z > right.Z);
  /// <summary>Per component, whether <paramref name="left"/>'s is greater than or equal to
  /// <paramref name="right"/>'s.</summary>
  public static Vector3b GreaterThanOrEqual(in Vector3d left, in Vector3d right) => new(
    left.X >= right.X, left.Y >= right.Y, left.Z >= right.Z);

  /// <summary>Each component blended by its own weight: <c>a + blend · (b − a)</c>.</summary>
  public static Vector3d Lerp(Vector3d a, Vector3d b, Vector3d blend) => new(
    blend.X * (b.X - a.X) + a.X, blend.Y * (b.Y - a.Y) + a.Y, blend.Z * (b.Z - a.Z) + a.Z);
  /// <summary><see cref="Lerp(Vector3d, Vector3d, Vector3d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Lerp(in Vector3d a, in Vector3d b, Vector3d blend, out Vector3d result) => result = Lerp(a, b, blend);

  /// <summary>
  /// Interpolates along the arc between the directions of <paramref name="a"/> and <paramref name="b"/> (their
  /// lengths weighted as the directions); falls back to <see cref="Lerp(Vector3d, Vector3d, double)"/> when either is zero or
  /// they are nearly parallel (|cos θ| > 0.9999), where the arc is ill-defined.
  /// </summary>
  public static Vector3d Slerp(Vector3d a, Vector3d b, double t)
  {
    double lengths = a.Length * b.Length;
    if (lengths == 0) return Lerp(a, b, t);
    double cos = Dot(a, b) / lengths;
    if (Math.Abs(cos) > 0.9999) return Lerp(a, b, t);
    double theta = Math.Acos(Math.Clamp(cos, -1, 1));
    double sin = Math.Sqrt(1 - cos * cos);
    return Math.Sin((1 - t) * theta) / sin * a + Math.Sin(t * theta) / sin * b;
  }

  /// <summary><see cref="Slerp(Vector3d, Vector3d, double)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Slerp(in Vector3d a, in Vector3d b, double t, out Vector3d result) => result = Slerp(a, b, t);

  /// <summary>Exponential interpolation, per component <c>a^(1 − t) · b^t</c> (for positive components).</summary>
  public static Vector3d Elerp(Vector3d a, Vector3d b, double t) => new(
    Math.Pow(a.X, 1 - t) * Math.Pow(b.X, t), Math.Pow(a.Y, 1 - t) * Math.Pow(b.Y, t), Math.Pow(a.Z, 1 - t) * Math.Pow(b.Z, t));
  /// <summary><see cref="Elerp(Vector3d, Vector3d, double)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Elerp(in Vector3d a, in Vector3d b, double t, out Vector3d result) => result = Elerp(a, b, t);
}
