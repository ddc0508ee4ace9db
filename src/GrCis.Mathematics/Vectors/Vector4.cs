using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>Single-precision 4D vector (OpenTK's name), for animated properties; also a row of <see cref="Matrix4"/>.</summary>
[Serializable]
[OpenTk3RefForms]
public partial struct Vector4 : IEquatable<Vector4>
{
  /// <summary>The components x, y, z and w.</summary>
  public float X, Y, Z, W;

  /// <summary>The vector (0, 0, 0, 0).</summary>
  public static readonly Vector4 Zero = new(0, 0, 0, 0);
  /// <summary>The vector (1, 1, 1, 1).</summary>
  public static readonly Vector4 One = new(1, 1, 1, 1);
  /// <summary>The vector (1, 0, 0, 0).</summary>
  public static readonly Vector4 UnitX = new(1, 0, 0, 0);
  /// <summary>The vector (0, 1, 0, 0).</summary>
  public static readonly Vector4 UnitY = new(0, 1, 0, 0);
  /// <summary>The vector (0, 0, 1, 0).</summary>
  public static readonly Vector4 UnitZ = new(0, 0, 1, 0);
  /// <summary>The vector (0, 0, 0, 1).</summary>
  public static readonly Vector4 UnitW = new(0, 0, 0, 1);

  /// <summary>The vector (x, y, z, w).</summary>
  public Vector4(float x, float y, float z, float w) { X = x; Y = y; Z = z; W = w; }
  /// <summary>A vector with every component equal to <paramref name="value"/>.</summary>
  public Vector4(float value) { X = Y = Z = W = value; }
  /// <summary>(x, y, 0, 0).</summary>
  public Vector4(Vector2 v) { X = v.X; Y = v.Y; Z = 0; W = 0; }
  /// <summary>(x, y, z, 0): a direction, as in OpenTK.</summary>
  public Vector4(Vector3 v) { X = v.X; Y = v.Y; Z = v.Z; W = 0; }
  /// <summary>The vector (v.X, v.Y, v.Z, w); w = 1 makes a point, w = 0 a direction.</summary>
  public Vector4(Vector3 v, float w) { X = v.X; Y = v.Y; Z = v.Z; W = w; }
  /// <summary>A copy of <paramref name="v"/>.</summary>
  public Vector4(Vector4 v) { X = v.X; Y = v.Y; Z = v.Z; W = v.W; }

  /// <summary>The component with index 0 (X), 1 (Y), 2 (Z) or 3 (W); any other index throws
  /// <see cref="System.IndexOutOfRangeException"/>.</summary>
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

  /// <summary>The components (x, y, z) as a Vector3; setting assigns them to X, Y, Z in the same order.</summary>
  public Vector3 Xyz { readonly get => new(X, Y, Z); set { X = value.X; Y = value.Y; Z = value.Z; } }
  /// <summary>The Euclidean length √(x² + y² + z² + w²).</summary>
  public readonly float Length => MathF.Sqrt(X * X + Y * Y + Z * Z + W * W);
  /// <summary>The squared length x² + y² + z² + w² (no square root).</summary>
  public readonly float LengthSquared => X * X + Y * Y + Z * Z + W * W;
  /// <summary>The length as 1 / <see cref="MathHelper.InverseSqrtFast(float)"/> of the squared length; that function is
  /// exact here, so this equals <see cref="Length"/> up to rounding.</summary>
  public readonly float LengthFast => 1f / MathHelper.InverseSqrtFast(LengthSquared);

  /// <summary>Scales the vector in place to unit length; a zero vector becomes NaN in every component.</summary>
  public void Normalize() { float s = 1f / Length; X *= s; Y *= s; Z *= s; W *= s; }
  /// <summary>Normalizes in place, exactly as <see cref="Normalize()"/> does (no approximation is used).</summary>
  public void NormalizeFast() { float s = MathHelper.InverseSqrtFast(LengthSquared); X *= s; Y *= s; Z *= s; W *= s; }
  /// <summary>A unit-length copy of the vector; a zero vector gives NaN in every component.</summary>
  public readonly Vector4 Normalized() { Vector4 v = this; v.Normalize(); return v; }

  /// <summary>Linear interpolation a + t·(b − a): a at t = 0, b at t = 1; t is not clamped.</summary>
  public static Vector4 Lerp(Vector4 a, Vector4 b, float t) => a + (b - a) * t;

  /// <summary>Row vector times matrix, in float, summed x to w as OpenTK does.</summary>
  public static Vector4 Transform(Vector4 vec, Matrix4 mat) => new(
    vec.X * mat.Row0.X + vec.Y * mat.Row1.X + vec.Z * mat.Row2.X + vec.W * mat.Row3.X,
    vec.X * mat.Row0.Y + vec.Y * mat.Row1.Y + vec.Z * mat.Row2.Y + vec.W * mat.Row3.Y,
    vec.X * mat.Row0.Z + vec.Y * mat.Row1.Z + vec.Z * mat.Row2.Z + vec.W * mat.Row3.Z,
    vec.X * mat.Row0.W + vec.Y * mat.Row1.W + vec.Z * mat.Row2.W + vec.W * mat.Row3.W);
  /// <summary><see cref="Transform(Vector4, Matrix4)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Transform(in Vector4 vec, in Matrix4 mat, out Vector4 result) => result = Transform(vec, mat);
  /// <summary>The row vector times the matrix, v · M, as <see cref="Transform(Vector4, Matrix4)"/>.</summary>
  public static Vector4 operator *(Vector4 vec, Matrix4 mat) => Transform(vec, mat);

  /// <summary>Matrix times column vector: each row of the matrix dotted with the vector.</summary>
  public static Vector4 Transform(Matrix4 mat, Vector4 vec) => new(Dot(mat.Row0, vec), Dot(mat.Row1, vec), Dot(mat.Row2, vec), Dot(mat.Row3, vec));
  /// <summary><see cref="Transform(Matrix4, Vector4)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Transform(in Matrix4 mat, in Vector4 vec, out Vector4 result) => result = Transform(mat, vec);
  /// <summary>The matrix times the column vector, M · v, as <see cref="Transform(Matrix4, Vector4)"/>.</summary>
  public static Vector4 operator *(Matrix4 mat, Vector4 vec) => Transform(mat, vec);

  /// <summary>The sum, component by component.</summary>
  public static Vector4 operator +(Vector4 a, Vector4 b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z, a.W + b.W);
  /// <summary>The difference, component by component.</summary>
  public static Vector4 operator -(Vector4 a, Vector4 b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z, a.W - b.W);
  /// <summary>The vector with every component negated.</summary>
  public static Vector4 operator -(Vector4 a) => new(-a.X, -a.Y, -a.Z, -a.W);
  /// <summary>Every component multiplied by the scalar.</summary>
  public static Vector4 operator *(Vector4 a, float s) => new(a.X * s, a.Y * s, a.Z * s, a.W * s);
  /// <summary>Every component multiplied by the scalar.</summary>
  public static Vector4 operator *(float s, Vector4 a) => new(a.X * s, a.Y * s, a.Z * s, a.W * s);
  /// <summary>The component-wise product (x·x', y·y', …), not a dot product.</summary>
  public static Vector4 operator *(Vector4 a, Vector4 b) => new(a.X * b.X, a.Y * b.Y, a.Z * b.Z, a.W * b.W);
  /// <summary>Every component divided by the scalar.</summary>
  public static Vector4 operator /(Vector4 a, float s) => new(a.X / s, a.Y / s, a.Z / s, a.W / s);
  /// <summary>Whether the two are equal, as <see cref="Equals(Vector4)"/> compares them.</summary>
  public static bool operator ==(Vector4 a, Vector4 b) => a.Equals(b);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Vector4)"/>.</summary>
  public static bool operator !=(Vector4 a, Vector4 b) => !a.Equals(b);

  /// <summary>Whether every component equals the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Vector4 other) => X == other.X && Y == other.Y && Z == other.Z && W == other.W;
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Vector4 v && Equals(v);
  /// <inheritdoc/>
  public override readonly int GetHashCode() => HashCode.Combine(X, Y, Z, W);
  /// <inheritdoc/>
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "({0}, {1}, {2}, {3})", X, Y, Z, W);
}
