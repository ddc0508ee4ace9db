using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>Single-precision 3D vector (OpenTK's name), for animated properties and meshes.</summary>
[Serializable]
[OpenTk3RefForms]
public partial struct Vector3 : IEquatable<Vector3>
{
  public float X, Y, Z;

  public static readonly Vector3 Zero = new(0, 0, 0);
  public static readonly Vector3 One = new(1, 1, 1);
  public static readonly Vector3 UnitX = new(1, 0, 0);
  public static readonly Vector3 UnitY = new(0, 1, 0);
  public static readonly Vector3 UnitZ = new(0, 0, 1);

  public Vector3(float x, float y, float z) { X = x; Y = y; Z = z; }
  public Vector3(float value) { X = Y = Z = value; }
  /// <summary>(x, y, 0).</summary>
  public Vector3(Vector2 v) { X = v.X; Y = v.Y; Z = 0; }
  public Vector3(Vector3 v) { X = v.X; Y = v.Y; Z = v.Z; }
  /// <summary>The first three components (w is dropped, not divided by).</summary>
  public Vector3(Vector4 v) { X = v.X; Y = v.Y; Z = v.Z; }

  public float this[int index]
  {
    readonly get => index switch { 0 => X, 1 => Y, 2 => Z, _ => throw new IndexOutOfRangeException($"Vector3 index {index} is outside 0..2.") };
    set
    {
      switch (index)
      {
        case 0: X = value; break;
        case 1: Y = value; break;
        case 2: Z = value; break;
        default: throw new IndexOutOfRangeException($"Vector3 index {index} is outside 0..2.");
      }
    }
  }

  public readonly float Length => MathF.Sqrt(X * X + Y * Y + Z * Z);
  public readonly float LengthSquared => X * X + Y * Y + Z * Z;
  public readonly float LengthFast => 1f / MathHelper.InverseSqrtFast(LengthSquared);

  public Vector2 Xy { readonly get => new(X, Y); set { X = value.X; Y = value.Y; } }
  public Vector2 Xz { readonly get => new(X, Z); set { X = value.X; Z = value.Y; } }
  public Vector2 Yx { readonly get => new(Y, X); set { Y = value.X; X = value.Y; } }
  public Vector2 Yz { readonly get => new(Y, Z); set { Y = value.X; Z = value.Y; } }
  public Vector2 Zx { readonly get => new(Z, X); set { Z = value.X; X = value.Y; } }
  public Vector2 Zy { readonly get => new(Z, Y); set { Z = value.X; Y = value.Y; } }
  public Vector3 Xzy { readonly get => new(X, Z, Y); set { X = value.X; Z = value.Y; Y = value.Z; } }
  public Vector3 Yxz { readonly get => new(Y, X, Z); set { Y = value.X; X = value.Y; Z = value.Z; } }
  public Vector3 Yzx { readonly get => new(Y, Z, X); set { Y = value.X; Z = value.Y; X = value.Z; } }
  public Vector3 Zxy { readonly get => new(Z, X, Y); set { Z = value.X; X = value.Y; Y = value.Z; } }
  public Vector3 Zyx { readonly get => new(Z, Y, X); set { Z = value.X; Y = value.Y; X = value.Z; } }

  public void Normalize() { float s = 1f / Length; X *= s; Y *= s; Z *= s; }
  public void NormalizeFast() { float s = MathHelper.InverseSqrtFast(LengthSquared); X *= s; Y *= s; Z *= s; }
  public readonly Vector3 Normalized() { float s = 1f / Length; return new(X * s, Y * s, Z * s); }
  public static float Dot(Vector3 a, Vector3 b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;
  public static Vector3 Cross(Vector3 a, Vector3 b) => new(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);
  public static Vector3 Lerp(Vector3 a, Vector3 b, float t) => a + (b - a) * t;

  // OpenTK 3's transforms by a float matrix (row vectors), in float and OpenTK's order. Transform treats the vector as a point (w = 1).
  public static Vector3 Transform(Vector3 vec, Matrix4 mat) => TransformPosition(vec, mat);
  public static void Transform(in Vector3 vec, in Matrix4 mat, out Vector3 result) => result = TransformPosition(vec, mat);
  public static Vector3 TransformPosition(Vector3 vec, Matrix4 mat) => new(
    vec.X * mat.Row0.X + vec.Y * mat.Row1.X + vec.Z * mat.Row2.X + mat.Row3.X,
    vec.X * mat.Row0.Y + vec.Y * mat.Row1.Y + vec.Z * mat.Row2.Y + mat.Row3.Y,
    vec.X * mat.Row0.Z + vec.Y * mat.Row1.Z + vec.Z * mat.Row2.Z + mat.Row3.Z);
  public static void TransformPosition(in Vector3 vec, in Matrix4 mat, out Vector3 result) => result = TransformPosition(vec, mat);
  public static Vector3 TransformVector(Vector3 vec, Matrix4 mat) => new(
    vec.X * mat.Row0.X + vec.Y * mat.Row1.X + vec.Z * mat.Row2.X,
    vec.X * mat.Row0.Y + vec.Y * mat.Row1.Y + vec.Z * mat.Row2.Y,
    vec.X * mat.Row0.Z + vec.Y * mat.Row1.Z + vec.Z * mat.Row2.Z);
  public static void TransformVector(in Vector3 vec, in Matrix4 mat, out Vector3 result) => result = TransformVector(vec, mat);
  /// <summary>By the inverse transpose of <paramref name="mat"/> (inverted in float); a singular matrix throws.</summary>
  public static Vector3 TransformNormal(Vector3 norm, Matrix4 mat) => TransformNormalInverse(norm, Matrix4.Invert(mat));
  public static void TransformNormal(in Vector3 norm, in Matrix4 mat, out Vector3 result) => result = TransformNormal(norm, mat);
  public static Vector3 TransformNormalInverse(Vector3 norm, Matrix4 invMat) => new(
    norm.X * invMat.Row0.X + norm.Y * invMat.Row0.Y + norm.Z * invMat.Row0.Z,
    norm.X * invMat.Row1.X + norm.Y * invMat.Row1.Y + norm.Z * invMat.Row1.Z,
    norm.X * invMat.Row2.X + norm.Y * invMat.Row2.Y + norm.Z * invMat.Row2.Z);
  public static float Distance(Vector3 a, Vector3 b) => (a - b).Length;
  public static float DistanceSquared(Vector3 a, Vector3 b) => (a - b).LengthSquared;

  public static Vector3 operator +(Vector3 a, Vector3 b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z);
  public static Vector3 operator -(Vector3 a, Vector3 b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z);
  public static Vector3 operator -(Vector3 a) => new(-a.X, -a.Y, -a.Z);
  public static Vector3 operator *(Vector3 a, float s) => new(a.X * s, a.Y * s, a.Z * s);
  public static Vector3 operator *(float s, Vector3 a) => new(a.X * s, a.Y * s, a.Z * s);
  public static Vector3 operator *(Vector3 a, Vector3 b) => new(a.X * b.X, a.Y * b.Y, a.Z * b.Z);
  public static Vector3 operator /(Vector3 a, float s) => new(a.X / s, a.Y / s, a.Z / s);
  public static bool operator ==(Vector3 a, Vector3 b) => a.Equals(b);
  public static bool operator !=(Vector3 a, Vector3 b) => !a.Equals(b);

  public readonly bool Equals(Vector3 other) => X == other.X && Y == other.Y && Z == other.Z;
  public override readonly bool Equals(object? obj) => obj is Vector3 v && Equals(v);
  public override readonly int GetHashCode() => HashCode.Combine(X, Y, Z);
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "({0}, {1}, {2})", X, Y, Z);
}
