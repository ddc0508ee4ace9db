using System;
using System.Runtime.CompilerServices;

namespace OpenTK.Mathematics;

// OpenTK 3's remaining static helpers of Vector3, with their ref/out twins (old code passes ref to avoid copies).
public partial struct Vector3
{
  /// <summary>The size of a Vector3 in memory, in bytes.</summary>
  public static readonly int SizeInBytes = Unsafe.SizeOf<Vector3>();

  /// <summary>The sum, component by component.</summary>
  public static Vector3 Add(Vector3 a, Vector3 b) => a + b;
  /// <summary><see cref="Add(Vector3, Vector3)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Add(in Vector3 a, in Vector3 b, out Vector3 result) => result = a + b;
  /// <summary>The difference, component by component.</summary>
  public static Vector3 Subtract(Vector3 a, Vector3 b) => a - b;
  /// <summary><see cref="Subtract(Vector3, Vector3)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Subtract(in Vector3 a, in Vector3 b, out Vector3 result) => result = a - b;
  /// <summary>Every component multiplied by the scalar.</summary>
  public static Vector3 Multiply(Vector3 vector, float scale) => vector * scale;
  /// <summary><see cref="Multiply(Vector3, float)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Multiply(in Vector3 vector, float scale, out Vector3 result) => result = vector * scale;
  /// <summary>The component-wise product (x·x', y·y', …), not a dot product.</summary>
  public static Vector3 Multiply(Vector3 vector, Vector3 scale) => vector * scale;
  /// <summary><see cref="Multiply(Vector3, Vector3)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Multiply(in Vector3 vector, in Vector3 scale, out Vector3 result) => result = vector * scale;
  /// <summary>Every component divided by the scalar.</summary>
  public static Vector3 Divide(Vector3 vector, float scale) => vector / scale;
  /// <summary><see cref="Divide(Vector3, float)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Divide(in Vector3 vector, float scale, out Vector3 result) => result = vector / scale;
  /// <summary>The component-wise quotient (x / x', y / y', …).</summary>
  public static Vector3 Divide(Vector3 vector, Vector3 scale) => new(vector.X / scale.X, vector.Y / scale.Y, vector.Z / scale.Z);
  /// <summary><see cref="Divide(Vector3, Vector3)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Divide(in Vector3 vector, in Vector3 scale, out Vector3 result) => result = Divide(vector, scale);

  /// <summary>The smaller of each pair of components.</summary>
  public static Vector3 ComponentMin(Vector3 a, Vector3 b) => new(MathF.Min(a.X, b.X), MathF.Min(a.Y, b.Y), MathF.Min(a.Z, b.Z));
  /// <summary><see cref="ComponentMin(Vector3, Vector3)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void ComponentMin(in Vector3 a, in Vector3 b, out Vector3 result) => result = ComponentMin(a, b);
  /// <summary>The larger of each pair of components.</summary>
  public static Vector3 ComponentMax(Vector3 a, Vector3 b) => new(MathF.Max(a.X, b.X), MathF.Max(a.Y, b.Y), MathF.Max(a.Z, b.Z));
  /// <summary><see cref="ComponentMax(Vector3, Vector3)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void ComponentMax(in Vector3 a, in Vector3 b, out Vector3 result) => result = ComponentMax(a, b);

  // OpenTK 3's Min/Max of Vector3 compare lengths (the older names of MagnitudeMin/MagnitudeMax); ties go to Max.
  /// <summary>The shorter of the two vectors (by squared length); on a tie, <paramref name="right"/>.</summary>
  public static Vector3 MagnitudeMin(Vector3 left, Vector3 right) => left.LengthSquared < right.LengthSquared ? left : right;
  /// <summary><see cref="MagnitudeMin(Vector3, Vector3)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void MagnitudeMin(in Vector3 left, in Vector3 right, out Vector3 result) => result = MagnitudeMin(left, right);
  /// <summary>The longer of the two vectors (by squared length); on a tie, <paramref name="left"/>.</summary>
  public static Vector3 MagnitudeMax(Vector3 left, Vector3 right) => left.LengthSquared >= right.LengthSquared ? left : right;
  /// <summary><see cref="MagnitudeMax(Vector3, Vector3)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void MagnitudeMax(in Vector3 left, in Vector3 right, out Vector3 result) => result = MagnitudeMax(left, right);
  /// <summary>The shorter of the two vectors, as <see cref="MagnitudeMin(Vector3, Vector3)"/> (OpenTK 3 compares
  /// lengths here, not components).</summary>
  public static Vector3 Min(Vector3 left, Vector3 right) => MagnitudeMin(left, right);
  /// <summary>The longer of the two vectors, as <see cref="MagnitudeMax(Vector3, Vector3)"/> (OpenTK 3 compares lengths
  /// here, not components).</summary>
  public static Vector3 Max(Vector3 left, Vector3 right) => MagnitudeMax(left, right);

  /// <summary>Each component clamped between the same components of <paramref name="min"/> and <paramref name="max"/>;
  /// min is tested first, and nothing throws when min &gt; max.</summary>
  public static Vector3 Clamp(Vector3 vec, Vector3 min, Vector3 max) =>
    new(MathHelper.ClampComponent(vec.X, min.X, max.X), MathHelper.ClampComponent(vec.Y, min.Y, max.Y), MathHelper.ClampComponent(vec.Z, min.Z, max.Z));
  /// <summary><see cref="Clamp(Vector3, Vector3, Vector3)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Clamp(in Vector3 vec, in Vector3 min, in Vector3 max, out Vector3 result) => result = Clamp(vec, min, max);

  /// <summary><see cref="Distance(Vector3, Vector3)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Distance(in Vector3 a, in Vector3 b, out float result) => result = Distance(a, b);
  /// <summary><see cref="DistanceSquared(Vector3, Vector3)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void DistanceSquared(in Vector3 a, in Vector3 b, out float result) => result = DistanceSquared(a, b);
  /// <summary>A unit-length copy of the vector, as <see cref="Normalized()"/>; a zero vector gives NaN
  /// components.</summary>
  public static Vector3 Normalize(Vector3 vec) => vec.Normalized();
  /// <summary><see cref="Normalize(Vector3)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Normalize(in Vector3 vec, out Vector3 result) => result = vec.Normalized();
  /// <summary>A unit-length copy, the same as <see cref="Normalize(Vector3)"/> (no approximation is used).</summary>
  public static Vector3 NormalizeFast(Vector3 vec) { vec.NormalizeFast(); return vec; }
  /// <summary><see cref="NormalizeFast(Vector3)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void NormalizeFast(in Vector3 vec, out Vector3 result) => result = NormalizeFast(vec);
  /// <summary><see cref="Dot(Vector3, Vector3)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Dot(in Vector3 a, in Vector3 b, out float result) => result = Dot(a, b);
  /// <summary><see cref="Cross(Vector3, Vector3)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Cross(in Vector3 a, in Vector3 b, out Vector3 result) => result = Cross(a, b);
  /// <summary><see cref="Lerp(Vector3, Vector3, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Lerp(in Vector3 a, in Vector3 b, float blend, out Vector3 result) => result = Lerp(a, b, blend);

  /// <summary>The point <c>a + u (b − a) + v (c − a)</c> of triangle abc.</summary>
  public static Vector3 BaryCentric(Vector3 a, Vector3 b, Vector3 c, float u, float v) => a + (b - a) * u + (c - a) * v;
  /// <summary><see cref="BaryCentric(Vector3, Vector3, Vector3, float, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void BaryCentric(in Vector3 a, in Vector3 b, in Vector3 c, float u, float v, out Vector3 result) =>
    result = BaryCentric(a, b, c, u, v);

  /// <summary>The angle between two vectors in radians, 0..π.</summary>
  public static float CalculateAngle(Vector3 first, Vector3 second) =>
    MathF.Acos(MathHelper.Clamp(Dot(first, second) / (first.Length * second.Length), -1f, 1f));
  /// <summary><see cref="CalculateAngle(Vector3, Vector3)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CalculateAngle(in Vector3 first, in Vector3 second, out float result) => result = CalculateAngle(first, second);
}
