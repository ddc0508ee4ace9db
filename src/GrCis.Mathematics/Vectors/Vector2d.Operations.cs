using System;
using System.Runtime.CompilerServices;

namespace OpenTK.Mathematics;

// OpenTK 3's remaining static helpers of Vector2d, with their ref/out twins (old code passes ref to avoid copies).
public partial struct Vector2d
{
  /// <summary>The size of a Vector2d in memory, in bytes.</summary>
  public static readonly int SizeInBytes = Unsafe.SizeOf<Vector2d>();

  /// <summary>The sum, component by component.</summary>
  public static Vector2d Add(Vector2d a, Vector2d b) => a + b;
  /// <summary><see cref="Add(Vector2d, Vector2d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Add(in Vector2d a, in Vector2d b, out Vector2d result) => result = a + b;
  /// <summary>The difference, component by component.</summary>
  public static Vector2d Subtract(Vector2d a, Vector2d b) => a - b;
  /// <summary><see cref="Subtract(Vector2d, Vector2d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Subtract(in Vector2d a, in Vector2d b, out Vector2d result) => result = a - b;
  /// <summary>Every component multiplied by the scalar.</summary>
  public static Vector2d Multiply(Vector2d vector, double scale) => vector * scale;
  /// <summary><see cref="Multiply(Vector2d, double)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Multiply(in Vector2d vector, double scale, out Vector2d result) => result = vector * scale;
  /// <summary>The component-wise product (x·x', y·y', …), not a dot product.</summary>
  public static Vector2d Multiply(Vector2d vector, Vector2d scale) => vector * scale;
  /// <summary><see cref="Multiply(Vector2d, Vector2d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Multiply(in Vector2d vector, in Vector2d scale, out Vector2d result) => result = vector * scale;
  /// <summary>Every component divided by the scalar.</summary>
  public static Vector2d Divide(Vector2d vector, double scale) => vector / scale;
  /// <summary><see cref="Divide(Vector2d, double)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Divide(in Vector2d vector, double scale, out Vector2d result) => result = vector / scale;
  /// <summary>The component-wise quotient (x / x', y / y', …).</summary>
  public static Vector2d Divide(Vector2d vector, Vector2d scale) => new(vector.X / scale.X, vector.Y / scale.Y);
  /// <summary><see cref="Divide(Vector2d, Vector2d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Divide(in Vector2d vector, in Vector2d scale, out Vector2d result) => result = Divide(vector, scale);

  // OpenTK 3's Min/Max of Vector2d are component-wise (unlike Vector3d's, which compare lengths).
  /// <summary>The smaller of each pair of components, as <see cref="ComponentMin(Vector2d, Vector2d)"/>.</summary>
  public static Vector2d Min(Vector2d a, Vector2d b) => ComponentMin(a, b);
  /// <summary><see cref="Min(Vector2d, Vector2d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Min(in Vector2d a, in Vector2d b, out Vector2d result) => result = ComponentMin(a, b);
  /// <summary>The larger of each pair of components, as <see cref="ComponentMax(Vector2d, Vector2d)"/>.</summary>
  public static Vector2d Max(Vector2d a, Vector2d b) => ComponentMax(a, b);
  /// <summary><see cref="Max(Vector2d, Vector2d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Max(in Vector2d a, in Vector2d b, out Vector2d result) => result = ComponentMax(a, b);
  /// <summary><see cref="ComponentMin(Vector2d, Vector2d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void ComponentMin(in Vector2d a, in Vector2d b, out Vector2d result) => result = ComponentMin(a, b);
  /// <summary><see cref="ComponentMax(Vector2d, Vector2d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void ComponentMax(in Vector2d a, in Vector2d b, out Vector2d result) => result = ComponentMax(a, b);
  /// <summary>The shorter of the two vectors (by squared length); on a tie, <paramref name="right"/>.</summary>
  public static Vector2d MagnitudeMin(Vector2d left, Vector2d right) => left.LengthSquared < right.LengthSquared ? left : right;
  /// <summary><see cref="MagnitudeMin(Vector2d, Vector2d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void MagnitudeMin(in Vector2d left, in Vector2d right, out Vector2d result) => result = MagnitudeMin(left, right);
  /// <summary>The longer of the two vectors (by squared length); on a tie, <paramref name="left"/>.</summary>
  public static Vector2d MagnitudeMax(Vector2d left, Vector2d right) => left.LengthSquared >= right.LengthSquared ? left : right;
  /// <summary><see cref="MagnitudeMax(Vector2d, Vector2d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void MagnitudeMax(in Vector2d left, in Vector2d right, out Vector2d result) => result = MagnitudeMax(left, right);
  /// <summary>Each component clamped between the same components of <paramref name="min"/> and <paramref name="max"/>;
  /// min is tested first, and nothing throws when min &gt; max.</summary>
  public static Vector2d Clamp(Vector2d vec, Vector2d min, Vector2d max) =>
    new(MathHelper.ClampComponent(vec.X, min.X, max.X), MathHelper.ClampComponent(vec.Y, min.Y, max.Y));
  /// <summary><see cref="Clamp(Vector2d, Vector2d, Vector2d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Clamp(in Vector2d vec, in Vector2d min, in Vector2d max, out Vector2d result) => result = Clamp(vec, min, max);

  /// <summary><see cref="Normalize(Vector2d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Normalize(in Vector2d vec, out Vector2d result) => result = vec.Normalized();
  /// <summary>A unit-length copy, the same as <see cref="Normalize(Vector2d)"/> (no approximation is used).</summary>
  public static Vector2d NormalizeFast(Vector2d vec) => vec.Normalized();
  /// <summary><see cref="NormalizeFast(Vector2d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void NormalizeFast(in Vector2d vec, out Vector2d result) => result = vec.Normalized();
  /// <summary><see cref="Dot(Vector2d, Vector2d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Dot(in Vector2d left, in Vector2d right, out double result) => result = Dot(left, right);
  /// <summary><see cref="Lerp(Vector2d, Vector2d, double)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Lerp(in Vector2d a, in Vector2d b, double blend, out Vector2d result) => result = Lerp(a, b, blend);

  /// <summary>The point <c>a + u (b − a) + v (c − a)</c> of triangle abc.</summary>
  public static Vector2d BaryCentric(Vector2d a, Vector2d b, Vector2d c, double u, double v) => a + (b - a) * u + (c - a) * v;
  /// <summary><see cref="BaryCentric(Vector2d, Vector2d, Vector2d, double, double)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void BaryCentric(in Vector2d a, in Vector2d b, in Vector2d c, double u, double v, out Vector2d result) =>
    result = BaryCentric(a, b, c, u, v);

  /// <summary>Rotates (x, y, 0) by the quaternion and keeps x and y.</summary>
  public static Vector2d Transform(Vector2d vec, Quaterniond quat) => Vector3d.Transform(new Vector3d(vec.X, vec.Y, 0), quat).Xy;
  /// <summary><see cref="Transform(Vector2d, Quaterniond)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Transform(in Vector2d vec, in Quaterniond quat, out Vector2d result) => result = Transform(vec, quat);
  /// <summary>OpenTK 4's operator form of <see cref="Transform(Vector2d, Quaterniond)"/>.</summary>
  public static Vector2d operator *(Quaterniond quat, Vector2d vec) => Transform(vec, quat);

  /// <summary>The single-precision vector widened to double (exact, though the conversion is explicit).</summary>
  public static explicit operator Vector2d(Vector2 v) => new(v.X, v.Y);
  /// <summary>Each component rounded to float.</summary>
  public static explicit operator Vector2(Vector2d v) => new((float)v.X, (float)v.Y);
}
