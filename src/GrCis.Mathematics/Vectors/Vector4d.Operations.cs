using System;
using System.Runtime.CompilerServices;

namespace OpenTK.Mathematics;

// OpenTK 3's remaining members of Vector4d, with the ref/out twins of the static helpers.
public partial struct Vector4d
{
  /// <summary>The size of a Vector4d in memory, in bytes.</summary>
  public static readonly int SizeInBytes = Unsafe.SizeOf<Vector4d>();

  /// <summary>(x, y, 0, 0).</summary>
  public Vector4d(Vector2d v) { X = v.X; Y = v.Y; Z = 0; W = 0; }
  /// <summary>(x, y, z, 0): a direction, as in OpenTK.</summary>
  public Vector4d(Vector3d v) { X = v.X; Y = v.Y; Z = v.Z; W = 0; }
  /// <summary>A copy of <paramref name="v"/>.</summary>
  public Vector4d(Vector4d v) { X = v.X; Y = v.Y; Z = v.Z; W = v.W; }

  /// <summary>The length as 1 / <see cref="MathHelper.InverseSqrtFast(double)"/> of the squared length; that function
  /// is exact here, so this equals <see cref="Length"/> up to rounding.</summary>
  public readonly double LengthFast => 1.0 / MathHelper.InverseSqrtFast(LengthSquared);
  /// <summary>Normalizes in place, exactly as <see cref="Normalize()"/> does (no approximation is used).</summary>
  public void NormalizeFast() => Normalize();

  /// <summary>The sum, component by component.</summary>
  public static Vector4d Add(Vector4d a, Vector4d b) => a + b;
  /// <summary><see cref="Add(Vector4d, Vector4d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Add(in Vector4d a, in Vector4d b, out Vector4d result) => result = a + b;
  /// <summary>The difference, component by component.</summary>
  public static Vector4d Subtract(Vector4d a, Vector4d b) => a - b;
  /// <summary><see cref="Subtract(Vector4d, Vector4d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Subtract(in Vector4d a, in Vector4d b, out Vector4d result) => result = a - b;
  /// <summary>Every component multiplied by the scalar.</summary>
  public static Vector4d Multiply(Vector4d vector, double scale) => vector * scale;
  /// <summary><see cref="Multiply(Vector4d, double)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Multiply(in Vector4d vector, double scale, out Vector4d result) => result = vector * scale;
  /// <summary>The component-wise product (x·x', y·y', …), not a dot product.</summary>
  public static Vector4d Multiply(Vector4d vector, Vector4d scale) => vector * scale;
  /// <summary><see cref="Multiply(Vector4d, Vector4d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Multiply(in Vector4d vector, in Vector4d scale, out Vector4d result) => result = vector * scale;
  /// <summary>Every component divided by the scalar.</summary>
  public static Vector4d Divide(Vector4d vector, double scale) => vector / scale;
  /// <summary><see cref="Divide(Vector4d, double)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Divide(in Vector4d vector, double scale, out Vector4d result) => result = vector / scale;
  /// <summary>The component-wise quotient (x / x', y / y', …).</summary>
  public static Vector4d Divide(Vector4d vector, Vector4d scale) => new(vector.X / scale.X, vector.Y / scale.Y, vector.Z / scale.Z, vector.W / scale.W);
  /// <summary><see cref="Divide(Vector4d, Vector4d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Divide(in Vector4d vector, in Vector4d scale, out Vector4d result) => result = Divide(vector, scale);

  // OpenTK 3's Min/Max of Vector4d are component-wise (unlike Vector3d's, which compare lengths).
  /// <summary>The smaller of each pair of components, as <see cref="ComponentMin(Vector4d, Vector4d)"/>.</summary>
  public static Vector4d Min(Vector4d a, Vector4d b) => ComponentMin(a, b);
  /// <summary><see cref="Min(Vector4d, Vector4d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Min(in Vector4d a, in Vector4d b, out Vector4d result) => result = ComponentMin(a, b);
  /// <summary>The larger of each pair of components, as <see cref="ComponentMax(Vector4d, Vector4d)"/>.</summary>
  public static Vector4d Max(Vector4d a, Vector4d b) => ComponentMax(a, b);
  /// <summary><see cref="Max(Vector4d, Vector4d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Max(in Vector4d a, in Vector4d b, out Vector4d result) => result = ComponentMax(a, b);
  /// <summary><see cref="ComponentMin(Vector4d, Vector4d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void ComponentMin(in Vector4d a, in Vector4d b, out Vector4d result) => result = ComponentMin(a, b);
  /// <summary><see cref="ComponentMax(Vector4d, Vector4d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void ComponentMax(in Vector4d a, in Vector4d b, out Vector4d result) => result = ComponentMax(a, b);
  /// <summary>The shorter of the two vectors (by squared length); on a tie, <paramref name="right"/>.</summary>
  public static Vector4d MagnitudeMin(Vector4d left, Vector4d right) => left.LengthSquared < right.LengthSquared ? left : right;
  /// <summary><see cref="MagnitudeMin(Vector4d, Vector4d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void MagnitudeMin(in Vector4d left, in Vector4d right, out Vector4d result) => result = MagnitudeMin(left, right);
  /// <summary>The longer of the two vectors (by squared length); on a tie, <paramref name="left"/>.</summary>
  public static Vector4d MagnitudeMax(Vector4d left, Vector4d right) => left.LengthSquared >= right.LengthSquared ? left : right;
  /// <summary><see cref="MagnitudeMax(Vector4d, Vector4d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void MagnitudeMax(in Vector4d left, in Vector4d right, out Vector4d result) => result = MagnitudeMax(left, right);
  /// <summary>Each component clamped between the same components of <paramref name="min"/> and <paramref name="max"/>;
  /// min is tested first, and nothing throws when min &gt; max.</summary>
  public static Vector4d Clamp(Vector4d vec, Vector4d min, Vector4d max) => new(
    MathHelper.ClampComponent(vec.X, min.X, max.X), MathHelper.ClampComponent(vec.Y, min.Y, max.Y), MathHelper.ClampComponent(vec.Z, min.Z, max.Z), MathHelper.ClampComponent(vec.W, min.W, max.W));
  /// <summary><see cref="Clamp(Vector4d, Vector4d, Vector4d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Clamp(in Vector4d vec, in Vector4d min, in Vector4d max, out Vector4d result) => result = Clamp(vec, min, max);

  /// <summary><see cref="Normalize(Vector4d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Normalize(in Vector4d vec, out Vector4d result) => result = vec.Normalized();
  /// <summary>A unit-length copy, the same as <see cref="Normalize(Vector4d)"/> (no approximation is used).</summary>
  public static Vector4d NormalizeFast(Vector4d vec) => vec.Normalized();
  /// <summary><see cref="NormalizeFast(Vector4d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void NormalizeFast(in Vector4d vec, out Vector4d result) => result = vec.Normalized();
  /// <summary><see cref="Dot(Vector4d, Vector4d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Dot(in Vector4d left, in Vector4d right, out double result) => result = Dot(left, right);
  /// <summary><see cref="Lerp(Vector4d, Vector4d, double)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Lerp(in Vector4d a, in Vector4d b, double blend, out Vector4d result) => result = Lerp(a, b, blend);
  /// <summary>The point <c>a + u (b − a) + v (c − a)</c> of triangle abc.</summary>
  public static Vector4d BaryCentric(Vector4d a, Vector4d b, Vector4d c, double u, double v) => a + (b - a) * u + (c - a) * v;
  /// <summary><see cref="BaryCentric(Vector4d, Vector4d, Vector4d, double, double)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void BaryCentric(in Vector4d a, in Vector4d b, in Vector4d c, double u, double v, out Vector4d result) =>
    result = BaryCentric(a, b, c, u, v);

  /// <summary>Rotates x, y, z by a unit quaternion; w is kept (the scalar part of q v q⁻¹).</summary>
  public static Vector4d Transform(Vector4d vec, Quaterniond quat) => new(Vector3d.Transform(vec.Xyz, quat), vec.W);
  /// <summary><see cref="Transform(Vector4d, Quaterniond)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Transform(in Vector4d vec, in Quaterniond quat, out Vector4d result) => result = Transform(vec, quat);
}
