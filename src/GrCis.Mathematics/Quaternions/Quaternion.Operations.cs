using System;

namespace OpenTK.Mathematics;

// OpenTK 3's static members of the float Quaternion: construction, interpolation and the ref/out twins.
public partial struct Quaternion
{
  public static Quaternion Add(Quaternion left, Quaternion right) => left + right;
  public static void Add(in Quaternion left, in Quaternion right, out Quaternion result) => result = left + right;
  public static Quaternion Sub(Quaternion left, Quaternion right) => left - right;
  public static void Sub(in Quaternion left, in Quaternion right, out Quaternion result) => result = left - right;
  public static Quaternion Multiply(Quaternion left, Quaternion right) => left * right;
  public static void Multiply(in Quaternion left, in Quaternion right, out Quaternion result) => result = left * right;
  public static Quaternion Multiply(Quaternion quaternion, float scale) => quaternion * scale;
  public static void Multiply(in Quaternion quaternion, float scale, out Quaternion result) => result = quaternion * scale;
  public static Quaternion Conjugate(Quaternion q) => new(-q.X, -q.Y, -q.Z, q.W);
  public static void Conjugate(in Quaternion q, out Quaternion result) => result = Conjugate(q);
  public static Quaternion Invert(Quaternion q) => q.Inverted();
  public static void Invert(in Quaternion q, out Quaternion result) => result = q.Inverted();
  public static Quaternion Normalize(Quaternion q) => q.Normalized();
  public static void Normalize(in Quaternion q, out Quaternion result) => result = q.Normalized();

  /// <summary>Rotation by <paramref name="angle"/> radians about <paramref name="axis"/> (identity for a zero axis).</summary>
  public static Quaternion FromAxisAngle(Vector3 axis, float angle)
  {
    if (axis.LengthSquared == 0f)
      return Identity;
    return new Quaternion(axis.Normalized() * MathF.Sin(0.5f * angle), MathF.Cos(0.5f * angle)).Normalized();
  }

  public static Quaternion FromEulerAngles(float pitch, float yaw, float roll) => new(pitch, yaw, roll);
  public static Quaternion FromEulerAngles(Vector3 eulerAngles) => new(eulerAngles);
  public static void FromEulerAngles(in Vector3 eulerAngles, out Quaternion result) => result = new Quaternion(eulerAngles);

  /// <summary>
  /// The rotation of an orthonormal matrix (row vectors), the inverse of <see cref="Matrix3.CreateFromQuaternion(Quaternion)"/>
  /// as <see cref="Quaterniond.FromMatrix(Matrix3d)"/> is; computed in double and rounded.
  /// </summary>
  public static Quaternion FromMatrix(Matrix3 matrix) => (Quaternion)Quaterniond.FromMatrix(matrix);
  public static void FromMatrix(in Matrix3 matrix, out Quaternion result) => result = FromMatrix(matrix);

  /// <summary>
  /// Spherical interpolation along the shorter arc, linear when the two are within about 8° (then normalised);
  /// a zero input gives the other, equal or opposite inputs give <paramref name="q1"/>.
  /// </summary>
  public static Quaternion Slerp(Quaternion q1, Quaternion q2, float blend)
  {
    if (q1.LengthSquared == 0f)
      return q2.LengthSquared == 0f ? Identity : q2;
    if (q2.LengthSquared == 0f)
      return q1;
    float cos = q1.W * q2.W + Vector3.Dot(q1.Xyz, q2.Xyz);
    if (cos >= 1f || cos <= -1f)
      return q1;
    if (cos < 0f)
    {
      q2 = -1f * q2;
      cos = -cos;
    }
    float wa = 1f - blend, wb = blend;
    if (cos < 0.99f)
    {
      float half = MathF.Acos(cos), sin = MathF.Sin(half);
      wa = MathF.Sin(half * (1f - blend)) / sin;
      wb = MathF.Sin(half * blend) / sin;
    }
    Quaternion r = wa * q1 + wb * q2;
    return r.LengthSquared > 0f ? r.Normalized() : Identity;
  }
}
