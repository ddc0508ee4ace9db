using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>Single-precision 4D vector (OpenTK's name), for animated properties; also a row of <see cref="Matrix4"/>.</summary>
[Serializable]
[OpenTk3RefForms]
public partial struct Vector4 : IEquatable<Vector4>
{
  public float X, Y, Z, W;

  public static readonly Vector4 Zero = new(0, 0, 0, 0);
  public static readonly Vector4 One = new(1, 1, 1, 1);
  public static readonly Vector4 UnitX = new(1, 0, 0, 0);
  public static readonly Vector4 UnitY = new(0, 1, 0, 0);
  public static readonly Vector4 UnitZ = new(0, 0, 1, 0);
  public static readonly Vector4 UnitW = new(0, 0, 0, 1);

  public Vector4(float x, float y, float z, float w) { X = x; Y = y; Z = z; W = w; }
  public Vector4(float value) { X = Y = Z = W = value; }
  /// <summary>(x, y, 0, 0).</summary>
  public Vector4(Vector2 v) { X = v.X; Y = v.Y; Z = 0; W = 0; }
  /// <summary>(x, y, z, 0): a direction, as in OpenTK.</summary>
  public Vector4(Vector3 v) { X = v.X; Y = v.Y; Z = v.Z; W = 0; }
  public Vector4(Vector3 v, float w) { X = v.X; Y = v.Y; Z = v.Z; W = w; }
  public Vector4(Vector4 v) { X = v.X; Y = v.Y; Z = v.Z; W = v.W; }

  public float this[int index]
  {
    readonly get => index switch { 0 => X, 1 => Y, 2 => Z, 3 => W, _ => throw new IndexOutOfRangeException($"Vector4 index {index} is outside 0..3.") };
    set
    {
      switch (index)
      {
        case 0: X = value; break;
        case 1: Y = value; break;
        case 2: Z = value; break;
        case 3: W = value; break;
        default: throw new IndexOutOfRangeException($"Vector4 index {index} is outside 0..3.");
      }
    }
  }

  public Vector3 Xyz { readonly get => new(X, Y, Z); set { X = value.X; Y = value.Y; Z = value.Z; } }
  public readonly float Length => MathF.Sqrt(X * X + Y * Y + Z * Z + W * W);
  public readonly float LengthSquared => X * X + Y * Y + Z * Z + W * W;
  public readonly float LengthFast => 1f / MathHelper.InverseSqrtFast(LengthSquared);

  public void Normalize() { float s = 1f / Length; X *= s; Y *= s; Z *= s; W *= s; }
  public void NormalizeFast() { float s = MathHelper.InverseSqrtFast(LengthSquared); X *= s; Y *= s; Z *= s; W *= s; }
  public readonly Vector4 Normalized() { Vector4 v = this; v.Normalize(); return v; }

  public static Vector4 Lerp(Vector4 a, Vector4 b, float t) => a + (b - a) * t;

  /// <summary>Row vector times matrix, in float, summed x to w as OpenTK does.</summary>
  public static Vector4 Transform(Vector4 vec, Matrix4 mat) => new(
    vec.X * mat.Row0.X + vec.Y * mat.Row1.X + vec.Z * mat.Row2.X + vec.W * mat.Row3.X,
    vec.X * mat.Row0.Y + vec.Y * mat.Row1.Y + vec.Z * mat.Row2.Y + vec.W * mat.Row3.Y,
    vec.X * mat.Row0.Z + vec.Y * mat.Row1.Z + vec.Z * mat.Row2.Z + vec.W * mat.Row3.Z,
    vec.X * mat.Row0.W + vec.Y * mat.Row1.W + vec.Z * mat.Row2.W + vec.W * mat.Row3.W);
  public static void Transform(in Vector4 vec, in Matrix4 mat, out Vector4 result) => result = Transform(vec, mat);
  public static Vector4 operator *(Vector4 vec, Matrix4 mat) => Transform(vec, mat);

  /// <summary>Matrix times column vector: each row of the matrix dotted with the vector.</summary>
  public static Vector4 Transform(Matrix4 mat, Vector4 vec) => new(Dot(mat.Row0, vec), Dot(mat.Row1, vec), Dot(mat.Row2, vec), Dot(mat.Row3, vec));
  public static void Transform(in Matrix4 mat, in Vector4 vec, out Vector4 result) => result = Transform(mat, vec);
  public static Vector4 operator *(Matrix4 mat, Vector4 vec) => Transform(mat, vec);

  public static Vector4 operator +(Vector4 a, Vector4 b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z, a.W + b.W);
  public static Vector4 operator -(Vector4 a, Vector4 b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z, a.W - b.W);
  public static Vector4 operator -(Vector4 a) => new(-a.X, -a.Y, -a.Z, -a.W);
  public static Vector4 operator *(Vector4 a, float s) => new(a.X * s, a.Y * s, a.Z * s, a.W * s);
  public static Vector4 operator *(float s, Vector4 a) => new(a.X * s, a.Y * s, a.Z * s, a.W * s);
  public static Vector4 operator *(Vector4 a, Vector4 b) => new(a.X * b.X, a.Y * b.Y, a.Z * b.Z, a.W * b.W);
  public static Vector4 operator /(Vector4 a, float s) => new(a.X / s, a.Y / s, a.Z / s, a.W / s);
  public static bool operator ==(Vector4 a, Vector4 b) => a.Equals(b);
  public static bool operator !=(Vector4 a, Vector4 b) => !a.Equals(b);

  public readonly bool Equals(Vector4 other) => X == other.X && Y == other.Y && Z == other.Z && W == other.W;
  public override readonly bool Equals(object? obj) => obj is Vector4 v && Equals(v);
  public override readonly int GetHashCode() => HashCode.Combine(X, Y, Z, W);
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "({0}, {1}, {2}, {3})", X, Y, Z, W);
}
