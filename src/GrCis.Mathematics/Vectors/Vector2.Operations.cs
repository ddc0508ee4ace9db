using System;
using System.Runtime.CompilerServices;

namespace OpenTK.Mathematics;

// OpenTK 3's static helpers of Vector2, with their ref/out twins (old code passes ref to avoid copies).
public partial struct Vector2
{
  /// <summary>The size of a Vector2 in memory, in bytes.</summary>
  public static readonly int SizeInBytes = Unsafe.SizeOf<Vector2>();

  /// <summary>The sum, component by component.</summary>
  public static Vector2 Add(Vector2 a, Vector2 b) => a + b;
  /// <summary><see cref="Add(Vector2, Vector2)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Add(in Vector2 a, in Vector2 b, out Vector2 result) => result = a + b;
  /// <summary>The difference, component by component.</summary>
  public static Vector2 Subtract(Vector2 a, Vector2 b) => a - b;
  /// <summary><see cref="Subtract(Vector2, Vector2)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Subtract(in Vector2 a, in Vector2 b, out Vector2 result) => result = a - b;
  /// <summary>Every component multiplied by the scalar.</summary>
  public static Vector2 Multiply(Vector2 vector, float scale) => vector * scale;
  /// <summary><see cref="Multiply(Vector2, float)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Multiply(in Vector2 vector, float scale, out Vector2 result) => result = vector * scale;
  /// <summary>The component-wise product (x·x', y·y', …), not a dot product.</summary>
  public static Vector2 Multiply(Vector2 vector, Vector2 scale) => vector * scale;
  /// <summary><see cref="Multiply(Vector2, Vector2)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Multiply(in Vector2 vector, in Vector2 scale, out Vector2 result) => result = vector * scale;
  /// <summary>Every component divided by the scalar.</summary>
  public static Vector2 Divide(Vector2 vector, float scale) => vector / scale;
  /// <summary><see cref="Divide(Vector2, float)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Divide(in Vector2 vector, float scale, out Vector2 result) => result = vector / scale;
  /// <summary>The component-wise quotient (x / x', y / y', …).</summary>
  public static Vector2 Divide(Vector2 vector, Vector2 scale) => new(vector.X / scale.X, vector.Y / scale.Y);
  /// <summary><see cref="Divide(Vector2, Vector2)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Divide(in Vector2 vector, in Vector2 scale, out Vector2 result) => result = Divide(vector, scale);

  /// <summary>The smaller of each pair of components.</summary>
  public static Vector2 ComponentMin(Vector2 a, Vector2 b) => new(MathF.Min(a.X, b.X), MathF.Min(a.Y, b.Y));
  /// <summary><see cref="ComponentMin(Vector2, Vector2)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void ComponentMin(in Vector2 a, in Vector2 b, out Vector2 result) => result = ComponentMin(a, b);
  /// <summary>The larger of each pair of components.</summary>
  public static Vector2 ComponentMax(Vector2 a, Vector2 b) => new(MathF.Max(a.X, b.X), MathF.Max(a.Y, b.Y));
  /// <summary><see cref="ComponentMax(Vector2, Vector2)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void ComponentMax(in Vector2 a, in Vector2 b, out Vector2 result) => result = ComponentMax(a, b);

  // OpenTK 3's Min/Max of the float Vector2 compare lengths, like Vector3's (Vector2d's are per component).
  /// <summary>The shorter of the two vectors (by squared length); on a tie, <paramref name="right"/>.</summary>
  public static Vector2 MagnitudeMin(Vector2 left, Vector2 right) => left.LengthSquared < right.LengthSquared ? left : right;
  /// <summary><see cref="MagnitudeMin(Vector2, Vector2)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void MagnitudeMin(in Vector2 left, in Vector2 right, out Vector2 result) => result = MagnitudeMin(left, right);
  /// <summary>The longer of the two vectors (by squared length); on a tie, <paramref name="left"/>.</summary>
  public static Vector2 MagnitudeMax(Vector2 left, Vector2 right) => left.LengthSquared >= right.LengthSquared ? left : right;
  /// <summary><see cref="MagnitudeMax(Vector2, Vector2)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void MagnitudeMax(in Vector2 left, in Vector2 right, out Vector2 result) => result = MagnitudeMax(left, right);
  /// <summary>The shorter of the two vectors, as <see cref="MagnitudeMin(Vector2, Vector2)"/> (OpenTK 3 compares
  /// lengths here, not components).</summary>
  public static Vector2 Min(Vector2 left, Vector2 right) => MagnitudeMin(left, right);
  /// <summary>The longer of the two vectors, as <see cref="MagnitudeMax(Vector2, Vector2)"/> (OpenTK 3 compares lengths
  /// here, not components).</summary>
  public static Vector2 Max(Vector2 left, Vector2 right) => MagnitudeMax(left, right);

  /// <summary>Each component clamped between the same components of <paramref name="min"/> and <paramref name="max"/>;
  /// min is tested first, and nothing throws when min &gt; max.</summary>
  public static Vector2 Clamp(Vector2 vec, Vector2 min, Vector2 max) =>
    new(MathHelper.ClampComponent(vec.X, min.X, max.X), MathHelper.ClampComponent(vec.Y, min.Y, max.Y));
  /// <summary><see cref="Clamp(Vector2, Vector2, Vector2)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Clamp(in Vector2 vec, in Vector2 min, in Vector2 max, out Vector2 result) => result = Clamp(vec, min, max);

  /// <summary>The Euclidean distance |a − b| between two points.</summary>
  public static float Distance(Vector2 a, Vector2 b) => (a - b).Length;
  /// <summary><see cref="Distance(Vector2, Vector2)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Distance(in Vector2 a, in Vector2 b, out float result) => result = Distance(a, b);
  /// <summary>The squared distance |a − b|² between two points (no square root).</summary>
  public static float DistanceSquared(Vector2 a, Vector2 b) => (a - b).LengthSquared;
  /// <summary><see cref="DistanceSquared(Vector2, Vector2)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void DistanceSquared(in Vector2 a, in Vector2 b, out float result) => result = DistanceSquared(a, b);

  /// <summary>A unit-length copy of the vector, as <see cref="Normalized()"/>; a zero vector gives NaN
  /// components.</summary>
  public static Vector2 Normalize(Vector2 vec) => vec.Normalized();
  /// <summary><see cref="Normalize(Vector2)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Normalize(in Vector2 vec, out Vector2 result) => result = vec.Normalized();
  /// <summary>A unit-length copy, the same as <see cref="Normalize(Vector2)"/> (no approximation is used).</summary>
  public static Vector2 NormalizeFast(Vector2 vec) { vec.NormalizeFast(); return vec; }
  /// <summary><see cref="NormalizeFast(Vector2)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void NormalizeFast(in Vector2 vec, out Vector2 result) => result = NormalizeFast(vec);

  /// <summary>The dot product: the sum of the products of corresponding components (x·x' + y·y' + …).</summary>
  public static float Dot(Vector2 a, Vector2 b) => a.X * b.X + a.Y * b.Y;
  /// <summary><see cref="Dot(Vector2, Vector2)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Dot(in Vector2 a, in Vector2 b, out float result) => result = Dot(a, b);
  /// <summary>The z of the 3D cross product of (a, 0) and (b, 0): positive when b is counter-clockwise of a.</summary>
  public static float PerpDot(Vector2 a, Vector2 b) => a.X * b.Y - a.Y * b.X;
  /// <summary><see cref="PerpDot(Vector2, Vector2)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void PerpDot(in Vector2 a, in Vector2 b, out float result) => result = PerpDot(a, b);

  /// <summary>Linear interpolation a + t·(b − a): a at t = 0, b at t = 1; t is not clamped.</summary>
  public static Vector2 Lerp(Vector2 a, Vector2 b, float blend) => a + (b - a) * blend;
  /// <summary><see cref="Lerp(Vector2, Vector2, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Lerp(in Vector2 a, in Vector2 b, float blend, out Vector2 result) => result = Lerp(a, b, blend);
  /// <summary>The point <c>a + u (b − a) + v (c − a)</c> of triangle abc.</summary>
  public static Vector2 BaryCentric(Vector2 a, Vector2 b, Vector2 c, float u, float v) => a + (b - a) * u + (c - a) * v;
  /// <summary><see cref="BaryCentric(Vector2, Vector2, Vector2, float, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void BaryCentric(in Vector2 a, in Vector2 b, in Vector2 c, float u, float v, out Vector2 result) =>
    result = BaryCentric(a, b, c, u, v);

  /// <summary>Rotates (x, y, 0) by the quaternion (<c>q v q⁻¹</c>) and keeps x and y.</summary>
  public static Vector2 Transform(Vector2 vec, Quaternion quat)
  {
    Quaternion r = quat * new Quaternion(vec.X, vec.Y, 0, 0) * quat.Inverted();
    return new Vector2(r.X, r.Y);
  }

  /// <summary><see cref="Transform(Vector2, Quaternion)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Transform(in Vector2 vec, in Quaternion quat, out Vector2 result) => result = Transform(vec, quat);
}
