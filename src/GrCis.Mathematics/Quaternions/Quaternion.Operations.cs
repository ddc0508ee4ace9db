using System;

namespace OpenTK.Mathematics;

// OpenTK 3's static members of the float Quaternion: construction, interpolation and the ref/out twins.
public partial struct Quaternion
{
  /// <summary>The sum, component by component (not a composition of rotations).</summary>
  public static Quaternion Add(Quaternion left, Quaternion right) => left + right;
  /// <summary><see cref="Add(Quaternion, Quaternion)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Add(in Quaternion left, in Quaternion right, out Quaternion result) => result = left + right;
  /// <summary>The difference, component by component.</summary>
  public static Quaternion Sub(Quaternion left, Quaternion right) => left - right;
  /// <summary><see cref="Sub(Quaternion, Quaternion)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Sub(in Quaternion left, in Quaternion right, out Quaternion result) => result = left - right;
  /// <summary>The Hamilton product <c>left * right</c>: rotating by it rotates by right first, then left.</summary>
  public static Quaternion Multiply(Quaternion left, Quaternion right) => left * right;
  /// <summary><see cref="Multiply(Quaternion, Quaternion)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Multiply(in Quaternion left, in Quaternion right, out Quaternion result) => result = left * right;
  /// <summary>Every component multiplied by the scalar.</summary>
  public static Quaternion Multiply(Quaternion quaternion, float scale) => quaternion * scale;
  /// <summary><see cref="Multiply(Quaternion, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Multiply(in Quaternion quaternion, float scale, out Quaternion result) => result = quaternion * scale;
  /// <summary>The conjugate (−x, −y, −z, w); for a unit quaternion, the inverse rotation.</summary>
  public static Quaternion Conjugate(Quaternion q) => new(-q.X, -q.Y, -q.Z, q.W);
  /// <summary><see cref="Conjugate(Quaternion)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Conjugate(in Quaternion q, out Quaternion result) => result = Conjugate(q);
  /// <summary>The inverse, as <see cref="Inverted()"/>: the conjugate over the squared length; a zero quaternion gives
  /// itself.</summary>
  public static Quaternion Invert(Quaternion q) => q.Inverted();
  /// <summary><see cref="Invert(Quaternion)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Invert(in Quaternion q, out Quaternion result) => result = q.Inverted();
  /// <summary>A unit-length copy of the quaternion, as <see cref="Normalized()"/>.</summary>
  public static Quaternion Normalize(Quaternion q) => q.Normalized();
  /// <summary><see cref="Normalize(Quaternion)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Normalize(in Quaternion q, out Quaternion result) => result = q.Normalized();

  /// <summary>Rotation by <paramref name="angle"/> radians about <paramref name="axis"/> (identity for a zero axis).</summary>
  public static Quaternion FromAxisAngle(Vector3 axis, float angle)
  {
    if (axis.LengthSquared == 0f)
      return Identity;
    return new Quaternion(axis.Normalized() * MathF.Sin(0.5f * angle), MathF.Cos(0.5f * angle)).Normalized();
  }

  /// <summary>The same as the constructor <see cref="Quaternion(float, float, float)"/>: the angles in radians are the
  /// rotations about X, Y and Z, multiplied as qX · qY · qZ.</summary>
  public static Quaternion FromEulerAngles(float pitch, float yaw, float roll) => new(pitch, yaw, roll);
  /// <summary>The same as <see cref="Quaternion(Vector3)"/>: rotations in radians about X, Y and Z (the vector's x, y,
  /// z), multiplied as qX · qY · qZ.</summary>
  public static Quaternion FromEulerAngles(Vector3 eulerAngles) => new(eulerAngles);
  /// <summary><see cref="FromEulerAngles(Vector3)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void FromEulerAngles(in Vector3 eulerAngles, out Quaternion result) => result = new Quaternion(eulerAngles);

  /// <summary>
  /// The rotation of an orthonormal matrix (row vectors), the inverse of <see cref="Matrix3.CreateFromQuaternion(Quaternion)"/>
  /// as <see cref="Quaterniond.FromMatrix(Matrix3d)"/> is; computed in double and rounded.
  /// </summary>
  public static Quaternion FromMatrix(Matrix3 matrix) => (Quaternion)Quaterniond.FromMatrix(matrix);
  /// <summary><see cref="FromMatrix(Matrix3)"/>, with the result written to <paramref name="result"/>.</summary>
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
