using System;
using System.Runtime.CompilerServices;

namespace OpenTK.Mathematics;

// OpenTK 3's static helpers of Vector4, with their ref/out twins (old code passes ref to avoid copies).
public partial struct Vector4
{
  /// <summary>The size of a Vector4 in memory, in bytes.</summary>
  public static readonly int SizeInBytes = Unsafe.SizeOf<Vector4>();

  /// <summary>The sum, component by component.</summary>
  public static Vector4 Add(Vector4 a, Vector4 b) => a + b;
  /// <summary><see cref="Add(Vector4, Vector4)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Add(in Vector4 a, in Vector4 b, out Vector4 result) => result = a + b;
  /// <summary>The difference, component by component.</summary>
  public static Vector4 Subtract(Vector4 a, Vector4 b) => a - b;
  /// <summary><see cref="Subtract(Vector4, Vector4)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Subtract(in Vector4 a, in Vector4 b, out Vector4 result) => result = a - b;
  /// <summary>Every component multiplied by the scalar.</summary>
  public static Vector4 Multiply(Vector4 vector, float scale) => vector * scale;
  /// <summary><see cref="Multiply(Vector4, float)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Multiply(in Vector4 vector, float scale, out Vector4 result) => result = vector * scale;
  /// <summary>The component-wise product (x·x', y·y', …), not a dot product.</summary>
  public static Vector4 Multiply(Vector4 vector, Vector4 scale) => vector * scale;
  /// <summary><see cref="Multiply(Vector4, Vector4)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Multiply(in Vector4 vector, in Vector4 scale, out Vector4 result) => result = vector * scale;
  /// <summary>Every component divided by the scalar.</summary>
  public static Vector4 Divide(Vector4 vector, float scale) => vector / scale;
  /// <summary><see cref="Divide(Vector4, float)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Divide(in Vector4 vector, float scale, out Vector4 result) => result = vector / scale;
  /// <summary>The component-wise quotient (x / x', y / y', …).</summary>
  public static Vector4 Divide(Vector4 vector, Vector4 scale) => new(vector.X / scale.X, vector.Y / scale.Y, vector.Z / scale.Z, vector.W / scale.W);
  /// <summary><see cref="Divide(Vector4, Vector4)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Divide(in Vector4 vector, in Vector4 scale, out Vector4 result) => result = Divide(vector, scale);

  /// <summary>The smaller of each pair of components.</summary>
  public static Vector4 ComponentMin(Vector4 a, Vector4 b) =>
    new(MathF.Min(a.X, b.X), MathF.Min(a.Y, b.Y), MathF.Min(a.Z, b.Z), MathF.Min(a.W, b.W));
  /// <summary><see cref="ComponentMin(Vector4, Vector4)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void ComponentMin(in Vector4 a, in Vector4 b, out Vector4 result) => result = ComponentMin(a, b);
  /// <summary>The larger of each pair of components.</summary>
  public static Vector4 ComponentMax(Vector4 a, Vector4 b) =>
    new(MathF.Max(a.X, b.X), MathF.Max(a.Y, b.Y), MathF.Max(a.Z, b.Z), MathF.Max(a.W, b.W));
  /// <summary><see cref="ComponentMax(Vector4, Vector4)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void ComponentMax(in Vector4 a, in Vector4 b, out Vector4 result) => result = ComponentMax(a, b);

  // OpenTK 3's Min/Max of Vector4 are per component (unlike Vector2's and Vector3's, which compare lengths).
  /// <summary>The smaller of each pair of components, as <see cref="ComponentMin(Vector4, Vector4)"/>.</summary>
  public static Vector4 Min(Vector4 a, Vector4 b) => ComponentMin(a, b);
  /// <summary><see cref="Min(Vector4, Vector4)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Min(in Vector4 a, in Vector4 b, out Vector4 result) => result = ComponentMin(a, b);
  /// <summary>The larger of each pair of components, as <see cref="ComponentMax(Vector4, Vector4)"/>.</summary>
  public static Vector4 Max(Vector4 a, Vector4 b) => ComponentMax(a, b);
  /// <summary><see cref="Max(Vector4, Vector4)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Max(in Vector4 a, in Vector4 b, out Vector4 result) => result = ComponentMax(a, b);
  /// <summary>The shorter of the two vectors (by squared length); on a tie, <paramref name="right"/>.</summary>
  public static Vector4 MagnitudeMin(Vector4 left, Vector4 right) => left.LengthSquared < right.LengthSquared ? left : right;
  /// <summary><see cref="MagnitudeMin(Vector4, Vector4)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void MagnitudeMin(in Vector4 left, in Vector4 right, out Vector4 result) => result = MagnitudeMin(left, right);
  /// <summary>The longer of the two vectors (by squared length); on a tie, <paramref name="left"/>.</summary>
  public static Vector4 MagnitudeMax(Vector4 left, Vector4 right) => left.LengthSquared >= right.LengthSquared ? left : right;
  /// <summary><see cref="MagnitudeMax(Vector4, Vector4)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void MagnitudeMax(in Vector4 left, in Vector4 right, out Vector4 result) => result = MagnitudeMax(left, right);

  /// <summary>Each component clamped between the same components of <paramref name="min"/> and <paramref name="max"/>;
  /// min is tested first, and nothing throws when min &gt; max.</summary>
  public static Vector4 Clamp(Vector4 vec, Vector4 min, Vector4 max) => new(
    MathHelper.ClampComponent(vec.X, min.X, max.X), MathHelper.ClampComponent(vec.Y, min.Y, max.Y), MathHelper.ClampComponent(vec.Z, min.Z, max.Z), MathHelper.ClampComponent(vec.W, min.W, max.W));
  /// <summary><see cref="Clamp(Vector4, Vector4, Vector4)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Clamp(in Vector4 vec, in Vector4 min, in Vector4 max, out Vector4 result) => result = Clamp(vec, min, max);

  /// <summary>A unit-length copy of the vector, as <see cref="Normalized()"/>; a zero vector gives NaN
  /// components.</summary>
  public static Vector4 Normalize(Vector4 vec) => vec.Normalized();
  /// <summary><see cref="Normalize(Vector4)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Normalize(in Vector4 vec, out Vector4 result) => result = vec.Normalized();
  /// <summary>A unit-length copy, the same as <see cref="Normalize(Vector4)"/> (no approximation is used).</summary>
  public static Vector4 NormalizeFast(Vector4 vec) { vec.NormalizeFast(); return vec; }
  /// <summary><see cref="NormalizeFast(Vector4)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void NormalizeFast(in Vector4 vec, out Vector4 result) => result = NormalizeFast(vec);

  /// <summary>The dot product: the sum of the products of corresponding components (x·x' + y·y' + …).</summary>
  public static float Dot(Vector4 a, Vector4 b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z + a.W * b.W;
  /// <summary><see cref="Dot(Vector4, Vector4)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Dot(in Vector4 a, in Vector4 b, out float result) => result = Dot(a, b);
  /// <summary><see cref="Lerp(Vector4, Vector4, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Lerp(in Vector4 a, in Vector4 b, float blend, out Vector4 result) => result = Lerp(a, b, blend);
  /// <summary>The point <c>a + u (b − a) + v (c − a)</c> of triangle abc.</summary>
  public static Vector4 BaryCentric(Vector4 a, Vector4 b, Vector4 c, float u, float v) => a + (b - a) * u + (c - a) * v;
  /// <summary><see cref="BaryCentric(Vector4, Vector4, Vector4, float, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void BaryCentric(in Vector4 a, in Vector4 b, in Vector4 c, float u, float v, out Vector4 result) =>
    result = BaryCentric(a, b, c, u, v);

  /// <summary><c>q v q⁻¹</c> with v as the quaternion (x, y, z, w): xyz rotated, w kept.</summary>
  public static Vector4 Transform(Vector4 vec, Quaternion quat)
  {
    Quaternion r = quat * new Quaternion(vec.X, vec.Y, vec.Z, vec.W) * quat.Inverted();
    return new Vector4(r.X, r.Y, r.Z, r.W);
  }

  /// <summary><see cref="Transform(Vector4, Quaternion)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Transform(in Vector4 vec, in Quaternion quat, out Vector4 result) => result = Transform(vec, quat);
  /// <summary><c>q v q⁻¹</c>, as <see cref="Transform(Vector4, Quaternion)"/>.</summary>
  public static Vector4 operator *(Quaternion quat, Vector4 vec) => Transform(vec, quat);
}
