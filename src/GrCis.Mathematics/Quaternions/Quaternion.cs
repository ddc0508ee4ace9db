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
  /// <summary>The components: X, Y, Z the vector part, W the scalar part.</summary>
  public float X, Y, Z, W;

  /// <summary>The identity rotation (0, 0, 0, 1).</summary>
  public static readonly Quaternion Identity = new(0, 0, 0, 1);

  /// <summary>The quaternion with vector part (x, y, z) and scalar part w (taken as given, not as an axis and
  /// angle).</summary>
  public Quaternion(float x, float y, float z, float w) { X = x; Y = y; Z = z; W = w; }
  /// <summary>The quaternion with vector part <paramref name="v"/> and scalar part <paramref name="w"/> (taken as
  /// given, not as an axis and angle).</summary>
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

  /// <summary>From Euler angles in radians, as <see cref="Quaternion(float, float, float)"/> with the vector's x, y and
  /// z.</summary>
  public Quaternion(Vector3 eulerAngles) : this(eulerAngles.X, eulerAngles.Y, eulerAngles.Z)
  {
  }

  /// <summary>The vector part (x, y, z); setting it leaves W unchanged.</summary>
  public Vector3 Xyz { readonly get => new(X, Y, Z); set { X = value.X; Y = value.Y; Z = value.Z; } }
  /// <summary>The Euclidean length √(x² + y² + z² + w²).</summary>
  public readonly float Length => MathF.Sqrt(LengthSquared);
  /// <summary>The squared length x² + y² + z² + w² (no square root).</summary>
  public readonly float LengthSquared => X * X + Y * Y + Z * Z + W * W;

  /// <summary>Scales the quaternion in place to unit length; a zero quaternion becomes NaN in every
  /// component.</summary>
  public void Normalize() { float s = 1f / Length; X *= s; Y *= s; Z *= s; W *= s; }
  /// <summary>A unit-length copy of the quaternion; a zero quaternion gives NaN in every component.</summary>
  public readonly Quaternion Normalized() { Quaternion q = this; q.Normalize(); return q; }
  /// <summary>Negates the vector part in place; for a unit quaternion this is the inverse rotation.</summary>
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

  /// <summary>Replaces the quaternion by its inverse, <see cref="Inverted()"/>; a zero quaternion stays zero.</summary>
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

  /// <summary>Every component multiplied by the scalar.</summary>
  public static Quaternion operator *(Quaternion q, float s) => new(q.X * s, q.Y * s, q.Z * s, q.W * s);
  /// <summary>Every component multiplied by the scalar.</summary>
  public static Quaternion operator *(float s, Quaternion q) => q * s;
  /// <summary>The sum, component by component (not a composition of rotations).</summary>
  public static Quaternion operator +(Quaternion a, Quaternion b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z, a.W + b.W);
  /// <summary>The difference, component by component.</summary>
  public static Quaternion operator -(Quaternion a, Quaternion b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z, a.W - b.W);
  /// <summary>Whether the two are equal, as <see cref="Equals(Quaternion)"/> compares them.</summary>
  public static bool operator ==(Quaternion a, Quaternion b) => a.Equals(b);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Quaternion)"/>.</summary>
  public static bool operator !=(Quaternion a, Quaternion b) => !a.Equals(b);

  /// <summary>The quaternion widened to double (exact).</summary>
  public static implicit operator Quaterniond(Quaternion q) => new(q.X, q.Y, q.Z, q.W);
  /// <summary>Each component rounded to float.</summary>
  public static explicit operator Quaternion(Quaterniond q) => new((float)q.X, (float)q.Y, (float)q.Z, (float)q.W);

  /// <summary>Whether every component equals the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Quaternion other) => X == other.X && Y == other.Y && Z == other.Z && W == other.W;
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Quaternion q && Equals(q);
  /// <inheritdoc/>
  public override readonly int GetHashCode() => HashCode.Combine(X, Y, Z, W);
  /// <inheritdoc/>
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "V: ({0}, {1}, {2}), W: {3}", X, Y, Z, W);
}
