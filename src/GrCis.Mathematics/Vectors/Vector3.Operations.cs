using System;
using System.Runtime.CompilerServices;

namespace OpenTK.Mathematics;

// OpenTK 3's remaining static helpers of Vector3, with their ref/out twins (old code passes ref to avoid copies).
public partial struct Vector3
{
  public static readonly int SizeInBytes = Unsafe.SizeOf<Vector3>();

  public static Vector3 Add(Vector3 a, Vector3 b) => a + b;
  public static void Add(in Vector3 a, in Vector3 b, out Vector3 result) => result = a + b;
  public static Vector3 Subtract(Vector3 a, Vector3 b) => a - b;
  public static void Subtract(in Vector3 a, in Vector3 b, out Vector3 result) => result = a - b;
  public static Vector3 Multiply(Vector3 vector, float scale) => vector * scale;
  public static void Multiply(in Vector3 vector, float scale, out Vector3 result) => result = vector * scale;
  public static Vector3 Multiply(Vector3 vector, Vector3 scale) => vector * scale;
  public static void Multiply(in Vector3 vector, in Vector3 scale, out Vector3 result) => result = vector * scale;
  public static Vector3 Divide(Vector3 vector, float scale) => vector / scale;
  public static void Divide(in Vector3 vector, float scale, out Vector3 result) => result = vector / scale;
  public static Vector3 Divide(Vector3 vector, Vector3 scale) => new(vector.X / scale.X, vector.Y / scale.Y, vector.Z / scale.Z);
  public static void Divide(in Vector3 vector, in Vector3 scale, out Vector3 result) => result = Divide(vector, scale);

  public static Vector3 ComponentMin(Vector3 a, Vector3 b) => new(MathF.Min(a.X, b.X), MathF.Min(a.Y, b.Y), MathF.Min(a.Z, b.Z));
  public static void ComponentMin(in Vector3 a, in Vector3 b, out Vector3 result) => result = ComponentMin(a, b);
  public static Vector3 ComponentMax(Vector3 a, Vector3 b) => new(MathF.Max(a.X, b.X), MathF.Max(a.Y, b.Y), MathF.Max(a.Z, b.Z));
  public static void ComponentMax(in Vector3 a, in Vector3 b, out Vector3 result) => result = ComponentMax(a, b);

  // OpenTK 3's Min/Max of Vector3 compare lengths (the older names of MagnitudeMin/MagnitudeMax); ties go to Max.
  public static Vector3 MagnitudeMin(Vector3 left, Vector3 right) => left.LengthSquared < right.LengthSquared ? left : right;
  public static void MagnitudeMin(in Vector3 left, in Vector3 right, out Vector3 result) => result = MagnitudeMin(left, right);
  public static Vector3 MagnitudeMax(Vector3 left, Vector3 right) => left.LengthSquared >= right.LengthSquared ? left : right;
  public static void MagnitudeMax(in Vector3 left, in Vector3 right, out Vector3 result) => result = MagnitudeMax(left, right);
  public static Vector3 Min(Vector3 left, Vector3 right) => MagnitudeMin(left, right);
  public static Vector3 Max(Vector3 left, Vector3 right) => MagnitudeMax(left, right);

  public static Vector3 Clamp(Vector3 vec, Vector3 min, Vector3 max) =>
    new(MathHelper.ClampComponent(vec.X, min.X, max.X), MathHelper.ClampComponent(vec.Y, min.Y, max.Y), MathHelper.ClampComponent(vec.Z, min.Z, max.Z));
  public static void Clamp(in Vector3 vec, in Vector3 min, in Vector3 max, out Vector3 result) => result = Clamp(vec, min, max);

  public static void Distance(in Vector3 a, in Vector3 b, out float result) => result = Distance(a, b);
  public static void DistanceSquared(in Vector3 a, in Vector3 b, out float result) => result = DistanceSquared(a, b);
  public static Vector3 Normalize(Vector3 vec) => vec.Normalized();
  public static void Normalize(in Vector3 vec, out Vector3 result) => result = vec.Normalized();
  public static Vector3 NormalizeFast(Vector3 vec) { vec.NormalizeFast(); return vec; }
  public static void NormalizeFast(in Vector3 vec, out Vector3 result) => result = NormalizeFast(vec);
  public static void Dot(in Vector3 a, in Vector3 b, out float result) => result = Dot(a, b);
  public static void Cross(in Vector3 a, in Vector3 b, out Vector3 result) => result = Cross(a, b);
  public static void Lerp(in Vector3 a, in Vector3 b, float blend, out Vector3 result) => result = Lerp(a, b, blend);

  /// <summary>The point <c>a + u (b − a) + v (c − a)</c> of triangle abc.</summary>
  public static Vector3 BaryCentric(Vector3 a, Vector3 b, Vector3 c, float u, float v) => a + (b - a) * u + (c - a) * v;
  public static void BaryCentric(in Vector3 a, in Vector3 b, in Vector3 c, float u, float v, out Vector3 result) =>
    result = BaryCentric(a, b, c, u, v);

  /// <summary>The angle between two vectors in radians, 0..π.</summary>
  public static float CalculateAngle(Vector3 first, Vector3 second) =>
    MathF.Acos(MathHelper.Clamp(Dot(first, second) / (first.Length * second.Length), -1f, 1f));
  public static void CalculateAngle(in Vector3 first, in Vector3 second, out float result) => result = CalculateAngle(first, second);
}
