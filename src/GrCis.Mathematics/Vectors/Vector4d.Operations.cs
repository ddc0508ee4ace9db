using System;
using System.Runtime.CompilerServices;

namespace OpenTK.Mathematics;

// OpenTK 3's remaining members of Vector4d, with the ref/out twins of the static helpers.
public partial struct Vector4d
{
  public static readonly int SizeInBytes = Unsafe.SizeOf<Vector4d>();

  /// <summary>(x, y, 0, 0).</summary>
  public Vector4d(Vector2d v) { X = v.X; Y = v.Y; Z = 0; W = 0; }
  /// <summary>(x, y, z, 0): a direction, as in OpenTK.</summary>
  public Vector4d(Vector3d v) { X = v.X; Y = v.Y; Z = v.Z; W = 0; }
  public Vector4d(Vector4d v) { X = v.X; Y = v.Y; Z = v.Z; W = v.W; }

  public readonly double LengthFast => 1.0 / MathHelper.InverseSqrtFast(LengthSquared);
  public void NormalizeFast() => Normalize();

  public static Vector4d Add(Vector4d a, Vector4d b) => a + b;
  public static void Add(in Vector4d a, in Vector4d b, out Vector4d result) => result = a + b;
  public static Vector4d Subtract(Vector4d a, Vector4d b) => a - b;
  public static void Subtract(in Vector4d a, in Vector4d b, out Vector4d result) => result = a - b;
  public static Vector4d Multiply(Vector4d vector, double scale) => vector * scale;
  public static void Multiply(in Vector4d vector, double scale, out Vector4d result) => result = vector * scale;
  public static Vector4d Multiply(Vector4d vector, Vector4d scale) => vector * scale;
  public static void Multiply(in Vector4d vector, in Vector4d scale, out Vector4d result) => result = vector * scale;
  public static Vector4d Divide(Vector4d vector, double scale) => vector / scale;
  public static void Divide(in Vector4d vector, double scale, out Vector4d result) => result = vector / scale;
  public static Vector4d Divide(Vector4d vector, Vector4d scale) => new(vector.X / scale.X, vector.Y / scale.Y, vector.Z / scale.Z, vector.W / scale.W);
  public static void Divide(in Vector4d vector, in Vector4d scale, out Vector4d result) => result = Divide(vector, scale);

  // OpenTK 3's Min/Max of Vector4d are component-wise (unlike Vector3d's, which compare lengths).
  public static Vector4d Min(Vector4d a, Vector4d b) => ComponentMin(a, b);
  public static void Min(in Vector4d a, in Vector4d b, out Vector4d result) => result = ComponentMin(a, b);
  public static Vector4d Max(Vector4d a, Vector4d b) => ComponentMax(a, b);
  public static void Max(in Vector4d a, in Vector4d b, out Vector4d result) => result = ComponentMax(a, b);
  public static void ComponentMin(in Vector4d a, in Vector4d b, out Vector4d result) => result = ComponentMin(a, b);
  public static void ComponentMax(in Vector4d a, in Vector4d b, out Vector4d result) => result = ComponentMax(a, b);
  public static Vector4d MagnitudeMin(Vector4d left, Vector4d right) => left.LengthSquared < right.LengthSquared ? left : right;
  public static void MagnitudeMin(in Vector4d left, in Vector4d right, out Vector4d result) => result = MagnitudeMin(left, right);
  public static Vector4d MagnitudeMax(Vector4d left, Vector4d right) => left.LengthSquared >= right.LengthSquared ? left : right;
  public static void MagnitudeMax(in Vector4d left, in Vector4d right, out Vector4d result) => result = MagnitudeMax(left, right);
  public static Vector4d Clamp(Vector4d vec, Vector4d min, Vector4d max) => new(
    MathHelper.ClampComponent(vec.X, min.X, max.X), MathHelper.ClampComponent(vec.Y, min.Y, max.Y), MathHelper.ClampComponent(vec.Z, min.Z, max.Z), MathHelper.ClampComponent(vec.W, min.W, max.W));
  public static void Clamp(in Vector4d vec, in Vector4d min, in Vector4d max, out Vector4d result) => result = Clamp(vec, min, max);

  public static void Normalize(in Vector4d vec, out Vector4d result) => result = vec.Normalized();
  public static Vector4d NormalizeFast(Vector4d vec) => vec.Normalized();
  public static void NormalizeFast(in Vector4d vec, out Vector4d result) => result = vec.Normalized();
  public static void Dot(in Vector4d left, in Vector4d right, out double result) => result = Dot(left, right);
  public static void Lerp(in Vector4d a, in Vector4d b, double blend, out Vector4d result) => result = Lerp(a, b, blend);
  public static Vector4d BaryCentric(Vector4d a, Vector4d b, Vector4d c, double u, double v) => a + (b - a) * u + (c - a) * v;
  public static void BaryCentric(in Vector4d a, in Vector4d b, in Vector4d c, double u, double v, out Vector4d result) =>
    result = BaryCentric(a, b, c, u, v);

  /// <summary>Rotates x, y, z by a unit quaternion; w is kept (the scalar part of q v q⁻¹).</summary>
  public static Vector4d Transform(Vector4d vec, Quaterniond quat) => new(Vector3d.Transform(vec.Xyz, quat), vec.W);
  public static void Transform(in Vector4d vec, in Quaterniond quat, out Vector4d result) => result = Transform(vec, quat);
}
