using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>Single-precision 2D vector (OpenTK's name).</summary>
[Serializable]
[OpenTk3RefForms]
public partial struct Vector2 : IEquatable<Vector2>
{
  public float X, Y;

  public static readonly Vector2 Zero = new(0, 0);
  public static readonly Vector2 One = new(1, 1);
  public static readonly Vector2 UnitX = new(1, 0);
  public static readonly Vector2 UnitY = new(0, 1);

  public Vector2(float x, float y) { X = x; Y = y; }
  public Vector2(float value) { X = Y = value; }

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

  public readonly float Length => MathF.Sqrt(X * X + Y * Y);
  public readonly float LengthSquared => X * X + Y * Y;
  public readonly float LengthFast => 1f / MathHelper.InverseSqrtFast(LengthSquared);
  /// <summary>Rotated a quarter turn clockwise: (y, −x).</summary>
  public readonly Vector2 PerpendicularRight => new(Y, -X);
  /// <summary>Rotated a quarter turn counter-clockwise: (−y, x).</summary>
  public readonly Vector2 PerpendicularLeft => new(-Y, X);
  public Vector2 Yx { readonly get => new(Y, X); set { Y = value.X; X = value.Y; } }

  public void Normalize() { float s = 1f / Length; X *= s; Y *= s; }
  public void NormalizeFast() { float s = MathHelper.InverseSqrtFast(LengthSquared); X *= s; Y *= s; }
  public readonly Vector2 Normalized() { float s = 1f / Length; return new(X * s, Y * s); }

  public static Vector2 operator +(Vector2 a, Vector2 b) => new(a.X + b.X, a.Y + b.Y);
  public static Vector2 operator -(Vector2 a, Vector2 b) => new(a.X - b.X, a.Y - b.Y);
  public static Vector2 operator -(Vector2 a) => new(-a.X, -a.Y);
  public static Vector2 operator *(Vector2 a, float s) => new(a.X * s, a.Y * s);
  public static Vector2 operator *(float s, Vector2 a) => new(a.X * s, a.Y * s);
  public static Vector2 operator *(Vector2 a, Vector2 b) => new(a.X * b.X, a.Y * b.Y);
  public static Vector2 operator /(Vector2 a, float s) => new(a.X / s, a.Y / s);
  public static bool operator ==(Vector2 a, Vector2 b) => a.Equals(b);
  public static bool operator !=(Vector2 a, Vector2 b) => !a.Equals(b);

  public readonly bool Equals(Vector2 other) => X == other.X && Y == other.Y;
  public override readonly bool Equals(object? obj) => obj is Vector2 v && Equals(v);
  public override readonly int GetHashCode() => HashCode.Combine(X, Y);
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "({0}, {1})", X, Y);
}
