using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>A double-precision rotation quaternion with OpenTK's names (X, Y, Z vector part, W scalar).</summary>
[Serializable]
[OpenTk3RefForms]
public partial struct Quaterniond : IEquatable<Quaterniond>
{
  /// <summary>The components: X, Y, Z the vector part, W the scalar part.</summary>
  public double X, Y, Z, W;

  /// <summary>The identity rotation (0, 0, 0, 1).</summary>
  public static readonly Quaterniond Identity = new(0, 0, 0, 1);

  /// <summary>The quaternion with vector part (x, y, z) and scalar part w (taken as given, not as an axis and
  /// angle).</summary>
  public Quaterniond(double x, double y, double z, double w) { X = x; Y = y; Z = z; W = w; }
  /// <summary>The quaternion with vector part <paramref name="v"/> and scalar part <paramref name="w"/> (taken as
  /// given, not as an axis and angle).</summary>
  public Quaterniond(Vector3d v, double w) { X = v.X; Y = v.Y; Z = v.Z; W = w; }

  /// <summary>
  /// From Euler angles in radians with OpenTK 3's double formula: the product <c>qX(roll) · qY(yaw) · qZ(pitch)</c>
  /// (pitch turns about Z and roll about X; a vector turns by pitch first). The float <see cref="Quaternion"/>'s
  /// constructor is <c>qX · qY · qZ</c> of its three angles, and <see cref="FromEulerAngles(in Vector3d, out Quaterniond)"/>
  /// has a third order: OpenTK 3's own, kept so old code gets the rotations it got.
  /// </summary>
  public Quaterniond(double pitch, double yaw, double roll)
  {
    double cp = Math.Cos(0.5 * pitch), sp = Math.Sin(0.5 * pitch);
    double cy = Math.Cos(0.5 * yaw), sy = Math.Sin(0.5 * yaw);
    double cr = Math.Cos(0.5 * roll), sr = Math.Sin(0.5 * roll);
    W = cy * cp * cr - sy * sp * sr;
    X = sy * sp * cr + cy * cp * sr;
    Y = sy * cp * cr - cy * sp * sr;
    Z = cy * sp * cr + sy * cp * sr;
  }

  /// <summary>The vector part (x, y, z); setting it leaves W unchanged.</summary>
  public Vector3d Xyz { readonly get => new(X, Y, Z); set { X = value.X; Y = value.Y; Z = value.Z; } }
  /// <summary>The Euclidean length √(x² + y² + z² + w²).</summary>
  public readonly double Length => Math.Sqrt(X * X + Y * Y + Z * Z + W * W);
  /// <summary>The squared length x² + y² + z² + w² (no square root).</summary>
  public readonly double LengthSquared => X * X + Y * Y + Z * Z + W * W;

  /// <summary>Scales the quaternion in place to unit length; a zero quaternion becomes NaN in every
  /// component.</summary>
  public void Normalize() { double s = 1.0 / Length; X *= s; Y *= s; Z *= s; W *= s; }
  /// <summary>A unit-length copy of the quaternion; a zero quaternion gives NaN in every component.</summary>
  public readonly Quaterniond Normalized() { Quaterniond q = this; q.Normalize(); return q; }
  /// <summary>A unit-length copy of the quaternion, as <see cref="Normalized()"/>.</summary>
  public static Quaterniond Normalize(Quaterniond q) => q.Normalized();
  /// <summary>Negates the vector part in place; for a unit quaternion this is the inverse rotation.</summary>
  public void Conjugate() { X = -X; Y = -Y; Z = -Z; }
  /// <summary>The conjugate (−x, −y, −z, w); for a unit quaternion, the inverse rotation.</summary>
  public static Quaterniond Conjugate(Quaterniond q) => new(-q.X, -q.Y, -q.Z, q.W);
  /// <summary>The conjugate divided by the squared length; a zero quaternion stays as it is.</summary>
  public readonly Quaterniond Inverted() { double l = LengthSquared; return l == 0 ? this : new(-X / l, -Y / l, -Z / l, W / l); }
  /// <summary>The inverse, as <see cref="Inverted()"/>: the conjugate over the squared length; a zero quaternion gives
  /// itself.</summary>
  public static Quaterniond Invert(Quaterniond q) => q.Inverted();
  /// <summary>Replaces the quaternion by its inverse, <see cref="Inverted()"/>; a zero quaternion stays zero.</summary>
  public void Invert() => this = Inverted();
  /// <summary>The 4D dot product x·x' + y·y' + z·z' + w·w' (the cosine of half the angle between two unit rotations, up
  /// to sign).</summary>
  public static double Dot(Quaterniond a, Quaterniond b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z + a.W * b.W;

  /// <summary>Rotation by <paramref name="angle"/> radians about <paramref name="axis"/>.</summary>
  public static Quaterniond FromAxisAngle(Vector3d axis, double angle)
  {
    if (axis.LengthSquared == 0.0) return Identity;
    Vector3d a = axis.Normalized() * Math.Sin(0.5 * angle);
    return new Quaterniond(a, Math.Cos(0.5 * angle)).Normalized();
  }

  /// <summary>The same as the constructor <see cref="Quaterniond(double, double, double)"/> (radians; see there for the
  /// order of the rotations).</summary>
  public static Quaterniond FromEulerAngles(double pitch, double yaw, double roll) => new(pitch, yaw, roll);
  /// <summary>The same as <see cref="Quaterniond(double, double, double)"/> with (x, y, z) as (pitch, yaw, roll), in
  /// radians.</summary>
  public static Quaterniond FromEulerAngles(Vector3d angles) => new(angles.X, angles.Y, angles.Z);

  /// <summary>The rotation's unit axis and its angle in radians (0..2π); for no rotation the axis is unit X. A
  /// quaternion with |w| &gt; 1 is normalized first.</summary>
  public readonly void ToAxisAngle(out Vector3d axis, out double angle)
  {
    Quaterniond q = Math.Abs(W) > 1.0 ? Normalized() : this;
    angle = 2.0 * Math.Acos(Math.Clamp(q.W, -1.0, 1.0));
    double den = Math.Sqrt(Math.Max(0.0, 1.0 - q.W * q.W));
    axis = den > 1e-12 ? new Vector3d(q.X / den, q.Y / den, q.Z / den) : Vector3d.UnitX;
  }

  /// <summary>The axis in x, y, z and the angle in radians in w, as
  /// <see cref="ToAxisAngle(out Vector3d, out double)"/>.</summary>
  public readonly Vector4d ToAxisAngle()
  {
    ToAxisAngle(out Vector3d axis, out double angle);
    return new Vector4d(axis, angle);
  }

  /// <summary>Spherical interpolation along the shorter arc.</summary>
  public static Quaterniond Slerp(Quaterniond a, Quaterniond b, double t)
  {
    if (a.LengthSquared == 0.0) return b.LengthSquared == 0.0 ? Identity : b;
    if (b.LengthSquared == 0.0) return a;
    double cos = Dot(a, b);
    if (cos < 0) { b = new Quaterniond(-b.X, -b.Y, -b.Z, -b.W); cos = -cos; }
    double wa, wb;
    if (cos < 0.99999)
    {
      double angle = Math.Acos(cos), sin = Math.Sin(angle);
      wa = Math.Sin((1.0 - t) * angle) / sin;
      wb = Math.Sin(t * angle) / sin;
    }
    else
    {
      wa = 1.0 - t; wb = t;   // nearly parallel: linear is exact enough and avoids 0/0
    }
    Quaterniond r = new(wa * a.X + wb * b.X, wa * a.Y + wb * b.Y, wa * a.Z + wb * b.Z, wa * a.W + wb * b.W);
    return r.LengthSquared > 0 ? r.Normalized() : Identity;
  }

  /// <summary>The Hamilton product <c>left * right</c>: rotating by it rotates by right first, then left.</summary>
  public static Quaterniond Multiply(Quaterniond a, Quaterniond b) => a * b;
  /// <summary>The sum, component by component (not a composition of rotations).</summary>
  public static Quaterniond Add(Quaterniond a, Quaterniond b) => a + b;
  /// <summary>The difference, component by component.</summary>
  public static Quaterniond Sub(Quaterniond a, Quaterniond b) => a - b;

  /// <summary>Hamilton product: rotating by the result rotates by <paramref name="b"/> first, then <paramref name="a"/>.</summary>
  public static Quaterniond operator *(Quaterniond a, Quaterniond b)
  {
    Vector3d av = a.Xyz, bv = b.Xyz;
    Vector3d v = b.W * av + a.W * bv + Vector3d.Cross(av, bv);
    return new Quaterniond(v, a.W * b.W - Vector3d.Dot(av, bv));
  }

  /// <summary>Every component multiplied by the scalar.</summary>
  public static Quaterniond operator *(Quaterniond q, double s) => new(q.X * s, q.Y * s, q.Z * s, q.W * s);
  /// <summary>Every component multiplied by the scalar.</summary>
  public static Quaterniond operator *(double s, Quaterniond q) => q * s;
  /// <summary>The sum, component by component (not a composition of rotations).</summary>
  public static Quaterniond operator +(Quaterniond a, Quaterniond b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z, a.W + b.W);
  /// <summary>The difference, component by component.</summary>
  public static Quaterniond operator -(Quaterniond a, Quaterniond b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z, a.W - b.W);
  /// <summary>Whether the two are equal, as <see cref="Equals(Quaterniond)"/> compares them.</summary>
  public static bool operator ==(Quaterniond a, Quaterniond b) => a.Equals(b);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Quaterniond)"/>.</summary>
  public static bool operator !=(Quaterniond a, Quaterniond b) => !a.Equals(b);

  /// <summary>Whether every component equals the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Quaterniond other) => X == other.X && Y == other.Y && Z == other.Z && W == other.W;
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Quaterniond q && Equals(q);
  /// <inheritdoc/>
  public override readonly int GetHashCode() => HashCode.Combine(X, Y, Z, W);
  /// <inheritdoc/>
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "V: ({0}, {1}, {2}), W: {3}", X, Y, Z, W);
}
