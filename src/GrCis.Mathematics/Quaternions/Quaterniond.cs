using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>A double-precision rotation quaternion with OpenTK's names (X, Y, Z vector part, W scalar).</summary>
[Serializable]
[OpenTk3RefForms]
public partial struct Quaterniond : IEquatable<Quaterniond>
{
  public double X, Y, Z, W;

  public static readonly Quaterniond Identity = new(0, 0, 0, 1);

  public Quaterniond(double x, double y, double z, double w) { X = x; Y = y; Z = z; W = w; }
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

  public Vector3d Xyz { readonly get => new(X, Y, Z); set { X = value.X; Y = value.Y; Z = value.Z; } }
  public readonly double Length => Math.Sqrt(X * X + Y * Y + Z * Z + W * W);
  public readonly double LengthSquared => X * X + Y * Y + Z * Z + W * W;

  public void Normalize() { double s = 1.0 / Length; X *= s; Y *= s; Z *= s; W *= s; }
  public readonly Quaterniond Normalized() { Quaterniond q = this; q.Normalize(); return q; }
  public static Quaterniond Normalize(Quaterniond q) => q.Normalized();
  public void Conjugate() { X = -X; Y = -Y; Z = -Z; }
  public static Quaterniond Conjugate(Quaterniond q) => new(-q.X, -q.Y, -q.Z, q.W);
  public readonly Quaterniond Inverted() { double l = LengthSquared; return l == 0 ? this : new(-X / l, -Y / l, -Z / l, W / l); }
  public static Quaterniond Invert(Quaterniond q) => q.Inverted();
  public void Invert() => this = Inverted();
  public static double Dot(Quaterniond a, Quaterniond b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z + a.W * b.W;

  /// <summary>Rotation by <paramref name="angle"/> radians about <paramref name="axis"/>.</summary>
  public static Quaterniond FromAxisAngle(Vector3d axis, double angle)
  {
    if (axis.LengthSquared == 0.0) return Identity;
    Vector3d a = axis.Normalized() * Math.Sin(0.5 * angle);
    return new Quaterniond(a, Math.Cos(0.5 * angle)).Normalized();
  }

  public static Quaterniond FromEulerAngles(double pitch, double yaw, double roll) => new(pitch, yaw, roll);
  public static Quaterniond FromEulerAngles(Vector3d angles) => new(angles.X, angles.Y, angles.Z);

  public readonly void ToAxisAngle(out Vector3d axis, out double angle)
  {
    Quaterniond q = Math.Abs(W) > 1.0 ? Normalized() : this;
    angle = 2.0 * Math.Acos(Math.Clamp(q.W, -1.0, 1.0));
    double den = Math.Sqrt(Math.Max(0.0, 1.0 - q.W * q.W));
    axis = den > 1e-12 ? new Vector3d(q.X / den, q.Y / den, q.Z / den) : Vector3d.UnitX;
  }

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

  public static Quaterniond Multiply(Quaterniond a, Quaterniond b) => a * b;
  public static Quaterniond Add(Quaterniond a, Quaterniond b) => a + b;
  public static Quaterniond Sub(Quaterniond a, Quaterniond b) => a - b;

  /// <summary>Hamilton product: rotating by the result rotates by <paramref name="b"/> first, then <paramref name="a"/>.</summary>
  public static Quaterniond operator *(Quaterniond a, Quaterniond b)
  {
    Vector3d av = a.Xyz, bv = b.Xyz;
    Vector3d v = b.W * av + a.W * bv + Vector3d.Cross(av, bv);
    return new Quaterniond(v, a.W * b.W - Vector3d.Dot(av, bv));
  }

  public static Quaterniond operator *(Quaterniond q, double s) => new(q.X * s, q.Y * s, q.Z * s, q.W * s);
  public static Quaterniond operator *(double s, Quaterniond q) => q * s;
  public static Quaterniond operator +(Quaterniond a, Quaterniond b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z, a.W + b.W);
  public static Quaterniond operator -(Quaterniond a, Quaterniond b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z, a.W - b.W);
  public static bool operator ==(Quaterniond a, Quaterniond b) => a.Equals(b);
  public static bool operator !=(Quaterniond a, Quaterniond b) => !a.Equals(b);

  public readonly bool Equals(Quaterniond other) => X == other.X && Y == other.Y && Z == other.Z && W == other.W;
  public override readonly bool Equals(object? obj) => obj is Quaterniond q && Equals(q);
  public override readonly int GetHashCode() => HashCode.Combine(X, Y, Z, W);
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "V: ({0}, {1}, {2}), W: {3}", X, Y, Z, W);
}
