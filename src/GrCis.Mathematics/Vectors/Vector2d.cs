using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>A 2D vector of doubles with OpenTK's names (texture coordinates, image points).</summary>
[Serializable]
[OpenTk3RefForms]
public partial struct Vector2d : IEquatable<Vector2d>
{
  /// <summary>The components x and y.</summary>
  public double X, Y;

  /// <summary>The vector (0, 0).</summary>
  public static readonly Vector2d Zero = new(0, 0);
  /// <summary>The vector (1, 1).</summary>
  public static readonly Vector2d One = new(1, 1);
  /// <summary>The vector (1, 0).</summary>
  public static readonly Vector2d UnitX = new(1, 0);
  /// <summary>The vector (0, 1).</summary>
  public static readonly Vector2d UnitY = new(0, 1);

  /// <summary>The vector (x, y).</summary>
  public Vector2d(double x, double y) { X = x; Y = y; }
  /// <summary>A vector with every component equal to <paramref name="value"/>.</summary>
  public Vector2d(double value) { X = Y = value; }

  /// <summary>The component with index 0 (X) or 1 (Y); any other index throws
  /// <see cref="System.IndexOutOfRangeException"/>.</summary>
  public double this[int index]
  {
    readonly get => index switch { 0 => X, 1 => Y, _ => throw new IndexOutOfRangeException($"Vector2d index {index} is outside 0..1.") };
    set
    {
      if (index == 0) X = value;
      else if (index == 1) Y = value;
      else throw new IndexOutOfRangeException($"Vector2d index {index} is outside 0..1.");
    }
  }

  /// <summary>The Euclidean length √(x² + y²).</summary>
  public readonly double Length => Math.Sqrt(X * X + Y * Y);
  /// <summary>The squared length x² + y² (no square root).</summary>
  public readonly double LengthSquared => X * X + Y * Y;
  /// <summary>Rotated a quarter turn clockwise: (y, −x).</summary>
  public readonly Vector2d PerpendicularRight => new(Y, -X);
  /// <summary>Rotated a quarter turn counter-clockwise: (−y, x).</summary>
  public readonly Vector2d PerpendicularLeft => new(-Y, X);
  /// <summary>The components (y, x) as a Vector2d; setting assigns them to Y, X in the same order.</summary>
  public Vector2d Yx { readonly get => new(Y, X); set { Y = value.X; X = value.Y; } }

  /// <summary>Scales the vector in place to unit length; a zero vector becomes NaN in every component.</summary>
  public void Normalize() { double s = 1.0 / Length; X *= s; Y *= s; }
  /// <summary>A unit-length copy of the vector; a zero vector gives NaN in every component.</summary>
  public readonly Vector2d Normalized() { double s = 1.0 / Length; return new(X * s, Y * s); }
  /// <summary>A unit-length copy of the vector, as <see cref="Normalized()"/>; a zero vector gives NaN
  /// components.</summary>
  public static Vector2d Normalize(Vector2d v) => v.Normalized();
  /// <summary>The dot product: the sum of the products of corresponding components (x·x' + y·y' + …).</summary>
  public static double Dot(Vector2d a, Vector2d b) => a.X * b.X + a.Y * b.Y;
  /// <summary>The Euclidean distance |a − b| between two points.</summary>
  public static double Distance(Vector2d a, Vector2d b) => (a - b).Length;

  /// <summary>The squared distance |a − b|² between two points (no square root).</summary>
  public static double DistanceSquared(Vector2d a, Vector2d b) => (a - b).LengthSquared;

  /// <summary><see cref="Distance(Vector2d, Vector2d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Distance(in Vector2d a, in Vector2d b, out double result) => result = Distance(a, b);

  /// <summary><see cref="DistanceSquared(Vector2d, Vector2d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void DistanceSquared(in Vector2d a, in Vector2d b, out double result) => result = DistanceSquared(a, b);
  /// <summary>Linear interpolation a + t·(b − a): a at t = 0, b at t = 1; t is not clamped.</summary>
  public static Vector2d Lerp(Vector2d a, Vector2d b, double t) => a + (b - a) * t;
  /// <summary>The smaller of each pair of components.</summary>
  public static Vector2d ComponentMin(Vector2d a, Vector2d b) => new(Math.Min(a.X, b.X), Math.Min(a.Y, b.Y));
  /// <summary>The larger of each pair of components.</summary>
  public static Vector2d ComponentMax(Vector2d a, Vector2d b) => new(Math.Max(a.X, b.X), Math.Max(a.Y, b.Y));

  /// <summary>The sum, component by component.</summary>
  public static Vector2d operator +(Vector2d a, Vector2d b) => new(a.X + b.X, a.Y + b.Y);
  /// <summary>The difference, component by component.</summary>
  public static Vector2d operator -(Vector2d a, Vector2d b) => new(a.X - b.X, a.Y - b.Y);
  /// <summary>The vector with every component negated.</summary>
  public static Vector2d operator -(Vector2d a) => new(-a.X, -a.Y);
  /// <summary>Every component multiplied by the scalar.</summary>
  public static Vector2d operator *(Vector2d a, double s) => new(a.X * s, a.Y * s);
  /// <summary>Every component multiplied by the scalar.</summary>
  public static Vector2d operator *(double s, Vector2d a) => new(a.X * s, a.Y * s);
  /// <summary>The component-wise product (x·x', y·y', …), not a dot product.</summary>
  public static Vector2d operator *(Vector2d a, Vector2d b) => new(a.X * b.X, a.Y * b.Y);
  /// <summary>Every component divided by the scalar.</summary>
  public static Vector2d operator /(Vector2d a, double s) => new(a.X / s, a.Y / s);
  /// <summary>Whether the two are equal, as <see cref="Equals(Vector2d)"/> compares them.</summary>
  public static bool operator ==(Vector2d a, Vector2d b) => a.Equals(b);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Vector2d)"/>.</summary>
  public static bool operator !=(Vector2d a, Vector2d b) => !a.Equals(b);

  /// <summary>Splits the vector into its components, for <c>var (x, y) = v;</c>.</summary>
  public readonly void Deconstruct(out double x, out double y) { x = X; y = Y; }
  /// <summary>Whether every component equals the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Vector2d other) => X == other.X && Y == other.Y;
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Vector2d v && Equals(v);
  /// <inheritdoc/>
  public override readonly int GetHashCode() => HashCode.Combine(X, Y);
  /// <inheritdoc/>
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "({0}, {1})", X, Y);
}
