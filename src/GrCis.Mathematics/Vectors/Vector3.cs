using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>Single-precision 3D vector (OpenTK's name), for animated properties and meshes.</summary>
[Serializable]
[OpenTk3RefForms]
public partial struct Vector3 : IEquatable<Vector3>
{
  /// <summary>The components x, y and z.</summary>
  public float X, Y, Z;

  /// <summary>The vector (0, 0, 0).</summary>
  public static readonly Vector3 Zero = new(0, 0, 0);
  /// <summary>The vector (1, 1, 1).</summary>
  public static readonly Vector3 One = new(1, 1, 1);
  /// <summary>The vector (1, 0, 0).</summary>
  public static readonly Vector3 UnitX = new(1, 0, 0);
  /// <summary>The vector (0, 1, 0).</summary>
  public static readonly Vector3 UnitY = new(0, 1, 0);
  /// <summary>The vector (0, 0, 1).</summary>
  public static readonly Vector3 UnitZ = new(0, 0, 1);

  /// <summary>The vector (x, y, z).</summary>
  public Vector3(float x, float y, float z) { X = x; Y = y; Z = z; }
  /// <summary>A vector with every component equal to <paramref name="value"/>.</summary>
  public Vector3(float value) { X = Y = Z = value; }
  /// <summary>(x, y, 0).</summary>
  public Vector3(Vector2 v) { X = v.X; Y = v.Y; Z = 0; }
  /// <summary>A copy of <paramref name="v"/>.</summary>
  public Vector3(Vector3 v) { X = v.X; Y = v.Y; Z = v.Z; }
  /// <summary>The first three components (w is dropped, not divided by).</summary>
  public Vector3(Vector4 v) { X = v.X; Y = v.Y; Z = v.Z; }

  /// <summary>The component with index 0 (X), 1 (Y) or 2 (Z); any other index throws
  /// <see cref="System.IndexOutOfRangeException"/>.</summary>
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

  /// <summary>The Euclidean length √(x² + y² + z²).</summary>
  public readonly float Length => MathF.Sqrt(X * X + Y * Y + Z * Z);
  /// <summary>The squared length x² + y² + z² (no square root).</summary>
  public readonly float LengthSquared => X * X + Y * Y + Z * Z;
  /// <summary>The length as 1 / <see cref="MathHelper.InverseSqrtFast(float)"/> of the squared length; that function is
  /// exact here, so this equals <see cref="Length"/> up to rounding.</summary>
  public readonly float LengthFast => 1f / MathHelper.InverseSqrtFast(LengthSquared);

  /// <summary>The components (x, y) as a Vector2; setting assigns them to X, Y in the same order.</summary>
  public Vector2 Xy { readonly get => new(X, Y); set { X = value.X; Y = value.Y; } }
  /// <summary>The components (x, z) as a Vector2; setting assigns them to X, Z in the same order.</summary>
  public Vector2 Xz { readonly get => new(X, Z); set { X = value.X; Z = value.Y; } }
  /// <summary>The components (y, x) as a Vector2; setting assigns them to Y, X in the same order.</summary>
  public Vector2 Yx { readonly get => new(Y, X); set { Y = value.X; X = value.Y; } }
  /// <summary>The components (y, z) as a Vector2; setting assigns them to Y, Z in the same order.</summary>
  public Vector2 Yz { readonly get => new(Y, Z); set { Y = value.X; Z = value.Y; } }
  /// <summary>The components (z, x) as a Vector2; setting assigns them to Z, X in the same order.</summary>
  public Vector2 Zx { readonly get => new(Z, X); set { Z = value.X; X = value.Y; } }
  /// <summary>The components (z, y) as a Vector2; setting assigns them to Z, Y in the same order.</summary>
  public Vector2 Zy { readonly get => new(Z, Y); set { Z = value.X; Y = value.Y; } }
  /// <summary>The components (x, z, y) as a Vector3; setting assigns them to X, Z, Y in the same order.</summary>
  public Vector3 Xzy { readonly get => new(X, Z, Y); set { X = value.X; Z = value.Y; Y = value.Z; } }
  /// <summary>The components (y, x, z) as a Vector3; setting assigns them to Y, X, Z in the same order.</summary>
  public Vector3 Yxz { readonly get => new(Y, X, Z); set { Y = value.X; X = value.Y; Z = value.Z; } }
  /// <summary>The components (y, z, x) as a Vector3; setting assigns them to Y, Z, X in the same order.</summary>
  public Vector3 Yzx { readonly get => new(Y, Z, X); set { Y = value.X; Z = value.Y; X = value.Z; } }
  /// <summary>The components (z, x, y) as a Vector3; setting assigns them to Z, X, Y in the same order.</summary>
  public Vector3 Zxy { readonly get => new(Z, X, Y); set { Z = value.X; X = value.Y; Y = value.Z; } }
  /// <summary>The components (z, y, x) as a Vector3; setting assigns them to Z, Y, X in the same order.</summary>
  public Vector3 Zyx { readonly get => new(Z, Y, X); set { Z = value.X; Y = value.Y; X = value.Z; } }

  /// <summary>Scales the vector in place to unit length; a zero vector becomes NaN in every component.</summary>
  public void Normalize() { float s = 1f / Length; X *= s; Y *= s; Z *= s; }
  /// <summary>Normalizes in place, exactly as <see cref="Normalize()"/> does (no approximation is used).</summary>
  public void NormalizeFast() { float s = MathHelper.InverseSqrtFast(LengthSquared); X *= s; Y *= s; Z *= s; }
  /// <summary>A unit-length copy of the vector; a zero vector gives NaN in every component.</summary>
  public readonly Vector3 Normalized() { float s = 1f / Length; return new(X * s, Y * s, Z * s); }
  /// <summary>The dot product: the sum of the products of corresponding components (x·x' + y·y' + …).</summary>
  public static float Dot(Vector3 a, Vector3 b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;
  /// <summary>The cross product a × b = (a.y·b.z − a.z·b.y, a.z·b.x − a.x·b.z, a.x·b.y − a.y·b.x),
  /// right-handed.</summary>
  public static Vector3 Cross(Vector3 a, Vector3 b) => new(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);
  /// <summary>Linear interpolation a + t·(b − a): a at t = 0, b at t = 1; t is not clamped.</summary>
  public static Vector3 Lerp(Vector3 a, Vector3 b, float t) => a + (b - a) * t;

  // OpenTK 3's transforms by a float matrix (row vectors), in float and OpenTK's order. Transform treats the vector as a point (w = 1).
  /// <summary>OpenTK 3's name of <see cref="TransformPosition(Vector3, Matrix4)"/>: the vector as a point (w = 1) times
  /// the matrix, without the perspective divide.</summary>
  public static Vector3 Transform(Vector3 vec, Matrix4 mat) => TransformPosition(vec, mat);
  /// <summary><see cref="Transform(Vector3, Matrix4)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Transform(in Vector3 vec, in Matrix4 mat, out Vector3 result) => result = TransformPosition(vec, mat);
  /// <summary>The point times the matrix, <c>(v, 1) * mat</c>: rotation, scale and the translation in Row3; no
  /// perspective divide.</summary>
  public static Vector3 TransformPosition(Vector3 vec, Matrix4 mat) => new(
    vec.X * mat.Row0.X + vec.Y * mat.Row1.X + vec.Z * mat.Row2.X + mat.Row3.X,
    vec.X * mat.Row0.Y + vec.Y * mat.Row1.Y + vec.Z * mat.Row2.Y + mat.Row3.Y,
    vec.X * mat.Row0.Z + vec.Y * mat.Row1.Z + vec.Z * mat.Row2.Z + mat.Row3.Z);
  /// <summary><see cref="TransformPosition(Vector3, Matrix4)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void TransformPosition(in Vector3 vec, in Matrix4 mat, out Vector3 result) => result = TransformPosition(vec, mat);
  /// <summary>The direction times the matrix, <c>(v, 0) * mat</c>: the upper 3×3 part only, translation
  /// ignored.</summary>
  public static Vector3 TransformVector(Vector3 vec, Matrix4 mat) => new(
    vec.X * mat.Row0.X + vec.Y * mat.Row1.X + vec.Z * mat.Row2.X,
    vec.X * mat.Row0.Y + vec.Y * mat.Row1.Y + vec.Z * mat.Row2.Y,
    vec.X * mat.Row0.Z + vec.Y * mat.Row1.Z + vec.Z * mat.Row2.Z);
  /// <summary><see cref="TransformVector(Vector3, Matrix4)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void TransformVector(in Vector3 vec, in Matrix4 mat, out Vector3 result) => result = TransformVector(vec, mat);
  /// <summary>By the inverse transpose of <paramref name="mat"/> (inverted in float); a singular matrix throws.</summary>
  public static Vector3 TransformNormal(Vector3 norm, Matrix4 mat) => TransformNormalInverse(norm, Matrix4.Invert(mat));
  /// <summary><see cref="TransformNormal(Vector3, Matrix4)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void TransformNormal(in Vector3 norm, in Matrix4 mat, out Vector3 result) => result = TransformNormal(norm, mat);
  /// <summary>Transforms a normal given the already inverted matrix: <c>invMat * n</c> with n as a column, i.e. n times
  /// the transpose of the upper 3×3 of <paramref name="invMat"/>.</summary>
  public static Vector3 TransformNormalInverse(Vector3 norm, Matrix4 invMat) => new(
    norm.X * invMat.Row0.X + norm.Y * invMat.Row0.Y + norm.Z * invMat.Row0.Z,
    norm.X * invMat.Row1.X + norm.Y * invMat.Row1.Y + norm.Z * invMat.Row1.Z,
    norm.X * invMat.Row2.X + norm.Y * invMat.Row2.Y + norm.Z * invMat.Row2.Z);
  /// <summary>The Euclidean distance |a − b| between two points.</summary>
  public static float Distance(Vector3 a, Vector3 b) => (a - b).Length;
  /// <summary>The squared distance |a − b|² between two points (no square root).</summary>
  public static float DistanceSquared(Vector3 a, Vector3 b) => (a - b).LengthSquared;

  /// <summary>The sum, component by component.</summary>
  public static Vector3 operator +(Vector3 a, Vector3 b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z);
  /// <summary>The difference, component by component.</summary>
  public static Vector3 operator -(Vector3 a, Vector3 b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z);
  /// <summary>The vector with every component negated.</summary>
  public static Vector3 operator -(Vector3 a) => new(-a.X, -a.Y, -a.Z);
  /// <summary>Every component multiplied by the scalar.</summary>
  public static Vector3 operator *(Vector3 a, float s) => new(a.X * s, a.Y * s, a.Z * s);
  /// <summary>Every component multiplied by the scalar.</summary>
  public static Vector3 operator *(float s, Vector3 a) => new(a.X * s, a.Y * s, a.Z * s);
  /// <summary>The component-wise product (x·x', y·y', …), not a dot product.</summary>
  public static Vector3 operator *(Vector3 a, Vector3 b) => new(a.X * b.X, a.Y * b.Y, a.Z * b.Z);
  /// <summary>Every component divided by the scalar.</summary>
  public static Vector3 operator /(Vector3 a, float s) => new(a.X / s, a.Y / s, a.Z / s);
  /// <summary>Whether the two are equal, as <see cref="Equals(Vector3)"/> compares them.</summary>
  public static bool operator ==(Vector3 a, Vector3 b) => a.Equals(b);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Vector3)"/>.</summary>
  public static bool operator !=(Vector3 a, Vector3 b) => !a.Equals(b);

  /// <summary>Whether every component equals the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Vector3 other) => X == other.X && Y == other.Y && Z == other.Z;
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Vector3 v && Equals(v);
  /// <inheritdoc/>
  public override readonly int GetHashCode() => HashCode.Combine(X, Y, Z);
  /// <inheritdoc/>
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "({0}, {1}, {2})", X, Y, Z);
}
