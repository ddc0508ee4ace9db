using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>Single-precision 2D vector (OpenTK's name).</summary>
[Serializable]
[OpenTk3RefForms]
public partial struct Vector2 : IEquatable<Vector2>
{
  /// <summary>The components x and y.</summary>
  public float X, Y;

  /// <summary>The vector (0, 0).</summary>
  public static readonly Vector2 Zero = new(0, 0);
  /// <summary>The vector (1, 1).</summary>
  public static readonly Vector2 One = new(1, 1);
  /// <summary>The vector (1, 0).</summary>
  public static readonly Vector2 UnitX = new(1, 0);
  /// <summary>The vector (0, 1).</summary>
  public static readonly Vector2 UnitY = new(0, 1);

  /// <summary>The vector (x, y).</summary>
  public Vector2(float x, float y) { X = x; Y = y; }
  /// <summary>A vector with every component equal to <paramref name="value"/>.</summary>
  public Vector2(float value) { X = Y = value; }

  /// <summary>The component with index 0 (X) or 1 (Y); any other index throws
  /// <see cref="System.IndexOutOfRangeException"/>.</summary>
  public float this[int index]
  {
    readonly get => index switch { 0 => X, 1 => Y, _ => throw new IndexOutOfRangeException($"Vector2 index {index} is outside 0..1.") };
    set
    {
      if (index == 0) X = value;
      else if (index == 1) Y = value;
      else throw new IndexOutOfRangeException($"Vector2 index {index} is outside 0..1.");
    }
  }

  /// <summary>The Euclidean length √(x² + y²).</summary>
  public readonly float Length => MathF.Sqrt(X * X + Y * Y);
  /// <summary>The squared length x² + y² (no square root).</summary>
  public readonly float LengthSquared => X * X + Y * Y;
  /// <summary>The length as 1 / <see cref="MathHelper.InverseSqrtFast(float)"/> of the squared length; that function is
  /// exact here, so this equals <see cref="Length"/> up to rounding.</summary>
  public readonly float LengthFast => 1f / MathHelper.InverseSqrtFast(LengthSquared);
  /// <summary>Rotated a quarter turn clockwise: (y, −x).</summary>
  public readonly Vector2 PerpendicularRight => new(Y, -X);
  /// <summary>Rotated a quarter turn counter-clockwise: (−y, x).</summary>
  public readonly Vector2 PerpendicularLeft => new(-Y, X);
  /// <summary>The components (y, x) as a Vector2; setting assigns them to Y, X in the same order.</summary>
  public Vector2 Yx { readonly get => new(Y, X); set { Y = value.X; X = value.Y; } }

  /// <summary>Scales the vector in place to unit length; a zero vector becomes NaN in every component.</summary>
  public void Normalize() { float s = 1f / Length; X *= s; Y *= s; }
  /// <summary>Normalizes in place, exactly as <see cref="Normalize()"/> does (no approximation is used).</summary>
  public void NormalizeFast() { float s = MathHelper.InverseSqrtFast(LengthSquared); X *= s; Y *= s; }
  /// <summary>A unit-length copy of the vector; a zero vector gives NaN in every component.</summary>
  public readonly Vector2 Normalized() { float s = 1f / Length; return new(X * s, Y * s); }

  /// <summary>The sum, component by component.</summary>
  public static Vector2 operator +(Vector2 a, Vector2 b) => new(a.X + b.X, a.Y + b.Y);
  /// <summary>The difference, component by component.</summary>
  public static Vector2 operator -(Vector2 a, Vector2 b) => new(a.X - b.X, a.Y - b.Y);
  /// <summary>The vector with every component negated.</summary>
  public static Vector2 operator -(Vector2 a) => new(-a.X, -a.Y);
  /// <summary>Every component multiplied by the scalar.</summary>
  public static Vector2 operator *(Vector2 a, float s) => new(a.X * s, a.Y * s);
  /// <summary>Every component multiplied by the scalar.</summary>
  public static Vector2 operator *(float s, Vector2 a) => new(a.X * s, a.Y * s);
  /// <summary>The component-wise product (x·x', y·y', …), not a dot product.</summary>
  public static Vector2 operator *(Vector2 a, Vector2 b) => new(a.X * b.X, a.Y * b.Y);
  /// <summary>Every component divided by the scalar.</summary>
  public static Vector2 operator /(Vector2 a, float s) => new(a.X / s, a.Y / s);
  /// <summary>Whether the two are equal, as <see cref="Equals(Vector2)"/> compares them.</summary>
  public static bool operator ==(Vector2 a, Vector2 b) => a.Equals(b);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Vector2)"/>.</summary>
  public static bool operator !=(Vector2 a, Vector2 b) => !a.Equals(b);

  /// <summary>Whether every component equals the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Vector2 other) => X == other.X && Y == other.Y;
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Vector2 v && Equals(v);
  /// <inheritdoc/>
  public override readonly int GetHashCode() => HashCode.Combine(X, Y);
  /// <inheritdoc/>
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "({0}, {1})", X, Y);
}
