using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>
/// OpenTK's single-precision rotation quaternion (X, Y, Z vector part, W scalar), computed in float as OpenTK 3
/// does. <see cref="Quaterniond"/> is the double-precision twin; the conversions between them are this port's.
/// </summary>
[Serializable]
[OpenTk3RefForms]
public partial struct Quaternion : IEquatable<Quaternion>
{
  public float X, Y, Z, W;

  public static readonly Quaternion Identity = new(0, 0, 0, 1);

  public Quaternion(float x, float y, float z, float w) { X = x; Y = y; Z = z; W = w; }
  public Quaternion(Vector3 v, float w) { X = v.X; Y = v.Y; Z = v.Z; W = w; }

  /// <summary>
  /// From Euler angles in radians, as OpenTK 3's float quaternion builds them: the product of the rotations
  /// about X, Y and Z in that order (<c>qx · qy · qz</c>, so a vector turns about Z first, X last).
  /// </summary>
  public Quaternion(float rotationX, float rotationY, float rotationZ)
  {
    // Sine and cosine in double rounded to float (not MathF), term order as OpenTK's: bit for bit its values.
    float hx = 0.5f * rotationX, hy = 0.5f * rotationY, hz = 0.5f * rotationZ;
    float cx = (float)Math.Cos(hx), sx = (float)Math.Sin(hx);
    float cy = (float)Math.Cos(hy), sy = (float)Math.Sin(hy);
    float cz = (float)Math.Cos(hz), sz = (float)Math.Sin(hz);
    W = cx * cy * cz - sx * sy * sz;
    X = sx * cy * cz + cx * sy * sz;
    Y = cx * sy * cz - sx * cy * sz;
    Z = cx * cy * sz + sx * sy * cz;
  }

  public Quaternion(Vector3 eulerAngles) : this(eulerAngles.X, eulerAngles.Y, eulerAngles.Z)
  {
  }

  public Vector3 Xyz { readonly get => new(X, Y, Z); set { X = value.X; Y = value.Y; Z = value.Z; } }
  public readonly float Length => MathF.Sqrt(LengthSquared);
  public readonly float LengthSquared => X * X + Y * Y + Z * Z + W * W;

  public void Normalize() { float s = 1f / Length; X *= s; Y *= s; Z *= s; W *= s; }
  public readonly Quaternion Normalized() { Quaternion q = this; q.Normalize(); return q; }
  public void Conjugate() { X = -X; Y = -Y; Z = -Z; }

  /// <summary>The conjugate divided by the squared length; a zero quaternion stays as it is.</summary>
  public readonly Quaternion Inverted()
  {
    float l = LengthSquared;
    if (l == 0)
      return this;
    float i = 1f / l;
    return new Quaternion(-X * i, -Y * i, -Z * i, W * i);
  }

  public void Invert() => this = Inverted();

  /// <summary>The rotation's axis (unit X for no rotation) and angle in radians.</summary>
  public readonly void ToAxisAngle(out Vector3 axis, out float angle)
  {
    Quaternion q = MathF.Abs(W) > 1f ? Normalized() : this;
    angle = 2f * MathF.Acos(q.W);
    float den = MathF.Sqrt(1f - q.W * q.W);
    axis = den > 1e-4f ? q.Xyz / den : Vector3.UnitX;
  }

  /// <summary>The axis in x, y, z and the angle in w.</summary>
  public readonly Vector4 ToAxisAngle()
  {
    ToAxisAngle(out Vector3 axis, out float angle);
    return new Vector4(axis, angle);
  }

  /// <summary>Hamilton product: rotating by the result rotates by <paramref name="b"/> first, then <paramref name="a"/>.</summary>
  public static Quaternion operator *(Quaternion a, Quaternion b)
  {
    Vector3 av = a.Xyz, bv = b.Xyz;
    return new Quaternion(b.W * av + a.W * bv + Vector3.Cross(av, bv), a.W * b.W - Vector3.Dot(av, bv));
  }

  public static Quaternion operator *(Quaternion q, float s) => new(q.X * s, q.Y * s, q.Z * s, q.W * s);
  public static Quaternion operator *(float s, Quaternion q) => q * s;
  public static Quaternion operator +(Quaternion a, Quaternion b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z, a.W + b.W);
  public static Quaternion operator -(Quaternion a, Quaternion b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z, a.W - b.W);
  public static bool operator ==(Quaternion a, Quaternion b) => a.Equals(b);
  public static bool operator !=(Quaternion a, Quaternion b) => !a.Equals(b);

  public static implicit operator Quaterniond(Quaternion q) => new(q.X, q.Y, q.Z, q.W);
  public static explicit operator Quaternion(Quaterniond q) => new((float)q.X, (float)q.Y, (float)q.Z, (float)q.W);

  public readonly bool Equals(Quaternion other) => X == other.X && Y == other.Y && Z == other.Z && W == other.W;
  public override readonly bool Equals(object? obj) => obj is Quaternion q && Equals(q);
  public override readonly int GetHashCode() => HashCode.Combine(X, Y, Z, W);
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "V: ({0}, {1}, {2}), W: {3}", X, Y, Z, W);
}
