using System;
using System.Globalization;
using System.Runtime.CompilerServices;

namespace OpenTK.Mathematics;

/// <summary>A 4D vector of doubles with OpenTK's names; also a matrix row.</summary>
[Serializable]
[OpenTk3RefForms]
public partial struct Vector4d : IEquatable<Vector4d>
{
  /// <summary>The components x, y, z and w.</summary>
  public double X, Y, Z, W;

  /// <summary>The vector (0, 0, 0, 0).</summary>
  public static readonly Vector4d Zero = new(0, 0, 0, 0);
  /// <summary>The vector (1, 1, 1, 1).</summary>
  public static readonly Vector4d One = new(1, 1, 1, 1);
  /// <summary>The vector (1, 0, 0, 0).</summary>
  public static readonly Vector4d UnitX = new(1, 0, 0, 0);
  /// <summary>The vector (0, 1, 0, 0).</summary>
  public static readonly Vector4d UnitY = new(0, 1, 0, 0);
  /// <summary>The vector (0, 0, 1, 0).</summary>
  public static readonly Vector4d UnitZ = new(0, 0, 1, 0);
  /// <summary>The vector (0, 0, 0, 1).</summary>
  public static readonly Vector4d UnitW = new(0, 0, 0, 1);

  /// <summary>The vector (x, y, z, w).</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public Vector4d(double x, double y, double z, double w) { X = x; Y = y; Z = z; W = w; }
  /// <summary>A vector with every component equal to <paramref name="value"/>.</summary>
  public Vector4d(double value) { X = Y = Z = W = value; }
  /// <summary>The vector (v.X, v.Y, v.Z, w); w = 1 makes a point, w = 0 a direction.</summary>
  public Vector4d(Vector3d v, double w) { X = v.X; Y = v.Y; Z = v.Z; W = w; }
  /// <summary>The vector (v.X, v.Y, z, w).</summary>
  public Vector4d(Vector2d v, double z, double w) { X = v.X; Y = v.Y; Z = z; W = w; }
  /// <summary>The single-precision vector widened to double (exact).</summary>
  public Vector4d(Vector4 v) { X = v.X; Y = v.Y; Z = v.Z; W = v.W; }

  /// <summary>The component with index 0 (X), 1 (Y), 2 (Z) or 3 (W); any other index throws
  /// <see cref="System.IndexOutOfRangeException"/>.</summary>
  public double this[int index]
  {
    readonly get => index switch { 0 => X, 1 => Y, 2 => Z, 3 => W, _ => throw new IndexOutOfRangeException($"Vector4d index {index} is outside 0..3.") };
    set
    {
      switch (index)
      {
        case 0: X = value; break;
        case 1: Y = value; break;
        case 2: Z = value; break;
        case 3: W = value; break;
        default: throw new IndexOutOfRangeException($"Vector4d index {index} is outside 0..3.");
      }
    }
  }

  /// <summary>The components (x, y, z) as a Vector3d; setting assigns them to X, Y, Z in the same order.</summary>
  public Vector3d Xyz { readonly get => new(X, Y, Z); set { X = value.X; Y = value.Y; Z = value.Z; } }
  /// <summary>The components (x, y) as a Vector2d; setting assigns them to X, Y in the same order.</summary>
  public Vector2d Xy { readonly get => new(X, Y); set { X = value.X; Y = value.Y; } }

  /// <summary>The Euclidean length √(x² + y² + z² + w²).</summary>
  public readonly double Length => Math.Sqrt(X * X + Y * Y + Z * Z + W * W);
  /// <summary>The squared length x² + y² + z² + w² (no square root).</summary>
  public readonly double LengthSquared => X * X + Y * Y + Z * Z + W * W;

  /// <summary>Scales the vector in place to unit length; a zero vector becomes NaN in every component.</summary>
  public void Normalize() { double s = 1.0 / Length; X *= s; Y *= s; Z *= s; W *= s; }
  /// <summary>A unit-length copy of the vector; a zero vector gives NaN in every component.</summary>
  public readonly Vector4d Normalized() { double s = 1.0 / Length; return new(X * s, Y * s, Z * s, W * s); }
  /// <summary>A unit-length copy of the vector, as <see cref="Normalized()"/>; a zero vector gives NaN
  /// components.</summary>
  public static Vector4d Normalize(Vector4d v) => v.Normalized();
  /// <summary>The dot product: the sum of the products of corresponding components (x·x' + y·y' + …).</summary>
  public static double Dot(Vector4d a, Vector4d b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z + a.W * b.W;
  /// <summary>Linear interpolation a + t·(b − a): a at t = 0, b at t = 1; t is not clamped.</summary>
  public static Vector4d Lerp(Vector4d a, Vector4d b, double t) => a + (b - a) * t;
  /// <summary>The smaller of each pair of components.</summary>
  public static Vector4d ComponentMin(Vector4d a, Vector4d b) => new(Math.Min(a.X, b.X), Math.Min(a.Y, b.Y), Math.Min(a.Z, b.Z), Math.Min(a.W, b.W));
  /// <summary>The larger of each pair of components.</summary>
  public static Vector4d ComponentMax(Vector4d a, Vector4d b) => new(Math.Max(a.X, b.X), Math.Max(a.Y, b.Y), Math.Max(a.Z, b.Z), Math.Max(a.W, b.W));

  /// <summary>Row vector times matrix: <c>v * m</c>.</summary>
  public static Vector4d Transform(Vector4d v, Matrix4d m) => new(
    v.X * m.Row0.X + v.Y * m.Row1.X + v.Z * m.Row2.X + v.W * m.Row3.X,
    v.X * m.Row0.Y + v.Y * m.Row1.Y + v.Z * m.Row2.Y + v.W * m.Row3.Y,
    v.X * m.Row0.Z + v.Y * m.Row1.Z + v.Z * m.Row2.Z + v.W * m.Row3.Z,
    v.X * m.Row0.W + v.Y * m.Row1.W + v.Z * m.Row2.W + v.W * m.Row3.W);
  /// <summary><see cref="Transform(Vector4d, Matrix4d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Transform(in Vector4d v, in Matrix4d m, out Vector4d result) => result = Transform(v, m);

  /// <summary>The sum, component by component.</summary>
  public static Vector4d operator +(Vector4d a, Vector4d b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z, a.W + b.W);
  /// <summary>The difference, component by component.</summary>
  public static Vector4d operator -(Vector4d a, Vector4d b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z, a.W - b.W);
  /// <summary>The vector with every component negated.</summary>
  public static Vector4d operator -(Vector4d a) => new(-a.X, -a.Y, -a.Z, -a.W);
  /// <summary>Every component multiplied by the scalar.</summary>
  public static Vector4d operator *(Vector4d a, double s) => new(a.X * s, a.Y * s, a.Z * s, a.W * s);
  /// <summary>Every component multiplied by the scalar.</summary>
  public static Vector4d operator *(double s, Vector4d a) => new(a.X * s, a.Y * s, a.Z * s, a.W * s);
  /// <summary>The component-wise product (x·x', y·y', …), not a dot product.</summary>
  public static Vector4d operator *(Vector4d a, Vector4d b) => new(a.X * b.X, a.Y * b.Y, a.Z * b.Z, a.W * b.W);
  /// <summary>The row vector times the matrix, v · M, as <see cref="Transform(Vector4d, Matrix4d)"/>.</summary>
  public static Vector4d operator *(Vector4d v, Matrix4d m) => Transform(v, m);
  /// <summary>Every component divided by the scalar.</summary>
  public static Vector4d operator /(Vector4d a, double s) => new(a.X / s, a.Y / s, a.Z / s, a.W / s);
  /// <summary>Whether the two are equal, as <see cref="Equals(Vector4d)"/> compares them.</summary>
  public static bool operator ==(Vector4d a, Vector4d b) => a.Equals(b);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Vector4d)"/>.</summary>
  public static bool operator !=(Vector4d a, Vector4d b) => !a.Equals(b);

  /// <summary>Each component rounded to float.</summary>
  public static explicit operator Vector4(Vector4d v) => new((float)v.X, (float)v.Y, (float)v.Z, (float)v.W);
  /// <summary>The single-precision vector widened to double (exact).</summary>
  public static implicit operator Vector4d(Vector4 v) => new(v.X, v.Y, v.Z, v.W);

  /// <summary>Splits the vector into its components, for <c>var (x, y, z, w) = v;</c>.</summary>
  public readonly void Deconstruct(out double x, out double y, out double z, out double w) { x = X; y = Y; z = Z; w = W; }
  /// <summary>Whether every component equals the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Vector4d other) => X == other.X && Y == other.Y && Z == other.Z && W == other.W;
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Vector4d v && Equals(v);
  /// <inheritdoc/>
  public override readonly int GetHashCode() => HashCode.Combine(X, Y, Z, W);
  /// <inheritdoc/>
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "({0}, {1}, {2}, {3})", X, Y, Z, W);
}
