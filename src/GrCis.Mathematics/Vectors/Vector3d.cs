using System;
using System.Globalization;
using System.Runtime.CompilerServices;

namespace OpenTK.Mathematics;

/// <summary>
/// A 3D vector of doubles with OpenTK's names and semantics (public fields, row-vector
/// transforms), so GrCis scripts written against OpenTK compile unchanged.
/// </summary>
[Serializable]
[OpenTk3RefForms]
public partial struct Vector3d : IEquatable<Vector3d>
{
  public double X, Y, Z;

  public static readonly Vector3d Zero = new(0, 0, 0);
  public static readonly Vector3d One = new(1, 1, 1);
  public static readonly Vector3d UnitX = new(1, 0, 0);
  public static readonly Vector3d UnitY = new(0, 1, 0);
  public static readonly Vector3d UnitZ = new(0, 0, 1);
  public static readonly Vector3d PositiveInfinity = new(double.PositiveInfinity, double.PositiveInfinity, double.PositiveInfinity);
  public static readonly Vector3d NegativeInfinity = new(double.NegativeInfinity, double.NegativeInfinity, double.NegativeInfinity);

  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public Vector3d(double x, double y, double z) { X = x; Y = y; Z = z; }
  public Vector3d(double value) { X = Y = Z = value; }
  public Vector3d(Vector2d v, double z) { X = v.X; Y = v.Y; Z = z; }
  public Vector3d(Vector3d v) { X = v.X; Y = v.Y; Z = v.Z; }
  public Vector3d(Vector4d v) { X = v.X; Y = v.Y; Z = v.Z; }
  public Vector3d(Vector3 v) { X = v.X; Y = v.Y; Z = v.Z; }

  public double this[int index]
  {
    readonly get => index switch { 0 => X, 1 => Y, 2 => Z, _ => throw new IndexOutOfRangeException($"Vector3d index {index} is outside 0..2.") };
    set
    {
      switch (index)
      {
        case 0: X = value; break;
        case 1: Y = value; break;
        case 2: Z = value; break;
        default: throw new IndexOutOfRangeException($"Vector3d index {index} is outside 0..2.");
      }
    }
  }

  public readonly double Length
  {
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    get => Math.Sqrt(X * X + Y * Y + Z * Z);
  }
  public readonly double LengthSquared => X * X + Y * Y + Z * Z;
  public readonly double LengthFast => 1.0 / MathHelper.InverseSqrtFast(LengthSquared);

  public Vector2d Xy { readonly get => new(X, Y); set { X = value.X; Y = value.Y; } }
  public Vector2d Xz { readonly get => new(X, Z); set { X = value.X; Z = value.Y; } }
  public Vector2d Yz { readonly get => new(Y, Z); set { Y = value.X; Z = value.Y; } }
  public Vector2d Yx { readonly get => new(Y, X); set { Y = value.X; X = value.Y; } }
  public Vector2d Zx { readonly get => new(Z, X); set { Z = value.X; X = value.Y; } }
  public Vector2d Zy { readonly get => new(Z, Y); set { Z = value.X; Y = value.Y; } }

  // OpenTK's three-component swizzles.
  public Vector3d Xzy { readonly get => new(X, Z, Y); set { X = value.X; Z = value.Y; Y = value.Z; } }
  public Vector3d Yxz { readonly get => new(Y, X, Z); set { Y = value.X; X = value.Y; Z = value.Z; } }
  public Vector3d Yzx { readonly get => new(Y, Z, X); set { Y = value.X; Z = value.Y; X = value.Z; } }
  public Vector3d Zxy { readonly get => new(Z, X, Y); set { Z = value.X; X = value.Y; Y = value.Z; } }
  public Vector3d Zyx { readonly get => new(Z, Y, X); set { Z = value.X; Y = value.Y; X = value.Z; } }

  /// <summary>Normalises this vector in place (OpenTK semantics).</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public void Normalize()
  {
    double s = 1.0 / Length;
    X *= s; Y *= s; Z *= s;
  }

  public void NormalizeFast() => Normalize();

  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public readonly Vector3d Normalized()
  {
    double s = 1.0 / Length;
    return new Vector3d(X * s, Y * s, Z * s);
  }

  public static Vector3d Normalize(Vector3d v) => v.Normalized();
  public static void Normalize(in Vector3d v, out Vector3d result) => result = v.Normalized();
  public static Vector3d NormalizeFast(Vector3d v) => v.Normalized();

  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static double Dot(Vector3d a, Vector3d b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;
  public static void Dot(in Vector3d a, in Vector3d b, out double result) => result = Dot(a, b);

  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector3d Cross(Vector3d a, Vector3d b) =>
    new(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);
  public static void Cross(in Vector3d a, in Vector3d b, out Vector3d result) => result = Cross(a, b);

  public static Vector3d Add(Vector3d a, Vector3d b) => a + b;
  public static Vector3d Subtract(Vector3d a, Vector3d b) => a - b;
  public static Vector3d Multiply(Vector3d a, double s) => a * s;
  public static Vector3d Multiply(Vector3d a, Vector3d b) => a * b;
  public static Vector3d Divide(Vector3d a, double s) => a / s;
  public static Vector3d Divide(Vector3d a, Vector3d b) => a / b;

  public static Vector3d ComponentMin(Vector3d a, Vector3d b) => new(Math.Min(a.X, b.X), Math.Min(a.Y, b.Y), Math.Min(a.Z, b.Z));
  public static Vector3d ComponentMax(Vector3d a, Vector3d b) => new(Math.Max(a.X, b.X), Math.Max(a.Y, b.Y), Math.Max(a.Z, b.Z));
  public static Vector3d Min(Vector3d a, Vector3d b) => a.LengthSquared < b.LengthSquared ? a : b;
  public static Vector3d Max(Vector3d a, Vector3d b) => a.LengthSquared >= b.LengthSquared ? a : b;
  public static Vector3d Clamp(Vector3d v, Vector3d min, Vector3d max) =>
    new(MathHelper.ClampComponent(v.X, min.X, max.X), MathHelper.ClampComponent(v.Y, min.Y, max.Y), MathHelper.ClampComponent(v.Z, min.Z, max.Z));
  public static Vector3d Abs(Vector3d v) => new(Math.Abs(v.X), Math.Abs(v.Y), Math.Abs(v.Z));

  public static double Distance(Vector3d a, Vector3d b) => (a - b).Length;
  public static double DistanceSquared(Vector3d a, Vector3d b) => (a - b).LengthSquared;

  public static Vector3d Lerp(Vector3d a, Vector3d b, double t) => a + (b - a) * t;

  public static Vector3d BaryCentric(Vector3d a, Vector3d b, Vector3d c, double u, double v) =>
    a + (b - a) * u + (c - a) * v;

  /// <summary>Angle between two vectors in radians.</summary>
  public static double CalculateAngle(Vector3d a, Vector3d b)
  {
    double d = Dot(a, b) / (a.Length * b.Length);
    return Math.Acos(Math.Clamp(d, -1.0, 1.0));
  }

  /// <summary>Row vector times matrix, ignoring translation: <c>(v, 0) * m</c>.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector3d TransformVector(Vector3d v, Matrix4d m) => new(
    v.X * m.Row0.X + v.Y * m.Row1.X + v.Z * m.Row2.X,
    v.X * m.Row0.Y + v.Y * m.Row1.Y + v.Z * m.Row2.Y,
    v.X * m.Row0.Z + v.Y * m.Row1.Z + v.Z * m.Row2.Z);
  public static void TransformVector(in Vector3d v, in Matrix4d m, out Vector3d result) => result = TransformVector(v, m);

  /// <summary>Row vector times matrix with translation: <c>(v, 1) * m</c>.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector3d TransformPosition(Vector3d v, Matrix4d m) => new(
    v.X * m.Row0.X + v.Y * m.Row1.X + v.Z * m.Row2.X + m.Row3.X,
    v.X * m.Row0.Y + v.Y * m.Row1.Y + v.Z * m.Row2.Y + m.Row3.Y,
    v.X * m.Row0.Z + v.Y * m.Row1.Z + v.Z * m.Row2.Z + m.Row3.Z);
  public static void TransformPosition(in Vector3d v, in Matrix4d m, out Vector3d result) => result = TransformPosition(v, m);

  /// <summary>Transforms a normal by the inverse transpose of <paramref name="m"/>; a singular m throws, as in OpenTK 3.</summary>
  public static Vector3d TransformNormal(Vector3d n, Matrix4d m) => TransformNormalInverse(n, Matrix4d.Invert(m));

  /// <summary>Transforms a normal, given the already inverted matrix: <c>invM * n</c> as a column.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector3d TransformNormalInverse(Vector3d n, Matrix4d invM) => new(
    n.X * invM.Row0.X + n.Y * invM.Row0.Y + n.Z * invM.Row0.Z,
    n.X * invM.Row1.X + n.Y * invM.Row1.Y + n.Z * invM.Row1.Z,
    n.X * invM.Row2.X + n.Y * invM.Row2.Y + n.Z * invM.Row2.Z);

  /// <summary>Homogeneous transform with the perspective divide.</summary>
  /// <summary>OpenTK 3's name: the vector as a point (w = 1), times the matrix, without the perspective divide.</summary>
  public static Vector3d Transform(Vector3d vec, Matrix4d mat) => TransformPosition(vec, mat);
  public static void Transform(in Vector3d vec, in Matrix4d mat, out Vector3d result) => result = TransformPosition(vec, mat);

  /// <summary>Row vector times a 3×3 matrix.</summary>
  public static Vector3d Transform(Vector3d vec, Matrix3d mat) => vec * mat;

  public static Vector3d TransformPerspective(Vector3d v, Matrix4d m)
  {
    Vector4d r = Vector4d.Transform(new Vector4d(v, 1.0), m);
    return new Vector3d(r.X / r.W, r.Y / r.W, r.Z / r.W);
  }

  public static Vector3d Transform(Vector3d v, Quaterniond q)
  {
    Vector3d u = q.Xyz;
    Vector3d t = 2.0 * Cross(u, v);
    return v + q.W * t + Cross(u, t);
  }

  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector3d operator +(Vector3d a, Vector3d b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z);
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector3d operator -(Vector3d a, Vector3d b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z);
  public static Vector3d operator -(Vector3d a) => new(-a.X, -a.Y, -a.Z);
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector3d operator *(Vector3d a, double s) => new(a.X * s, a.Y * s, a.Z * s);
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector3d operator *(double s, Vector3d a) => new(a.X * s, a.Y * s, a.Z * s);
  public static Vector3d operator *(Vector3d a, Vector3d b) => new(a.X * b.X, a.Y * b.Y, a.Z * b.Z);
  public static Vector3d operator /(Vector3d a, double s) { double inv = 1.0 / s; return new(a.X * inv, a.Y * inv, a.Z * inv); }
  public static Vector3d operator /(Vector3d a, Vector3d b) => new(a.X / b.X, a.Y / b.Y, a.Z / b.Z);
  public static bool operator ==(Vector3d a, Vector3d b) => a.Equals(b);
  public static bool operator !=(Vector3d a, Vector3d b) => !a.Equals(b);

  public static explicit operator Vector3(Vector3d v) => new((float)v.X, (float)v.Y, (float)v.Z);
  public static implicit operator Vector3d(Vector3 v) => new(v.X, v.Y, v.Z);
  public static implicit operator Vector3d((double X, double Y, double Z) t) => new(t.X, t.Y, t.Z);

  public readonly void Deconstruct(out double x, out double y, out double z) { x = X; y = Y; z = Z; }

  public readonly bool Equals(Vector3d other) => X == other.X && Y == other.Y && Z == other.Z;
  public override readonly bool Equals(object? obj) => obj is Vector3d v && Equals(v);
  public override readonly int GetHashCode() => HashCode.Combine(X, Y, Z);
  public override readonly string ToString() =>
    string.Format(CultureInfo.CurrentCulture, "({0}, {1}, {2})", X, Y, Z);
}
