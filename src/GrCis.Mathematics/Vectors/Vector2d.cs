using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>A 2D vector of doubles with OpenTK's names (texture coordinates, image points).</summary>
[Serializable]
[OpenTk3RefForms]
public partial struct Vector2d : IEquatable<Vector2d>
{
  public double X, Y;

  public static readonly Vector2d Zero = new(0, 0);
  public static readonly Vector2d One = new(1, 1);
  public static readonly Vector2d UnitX = new(1, 0);
  public static readonly Vector2d UnitY = new(0, 1);

  public Vector2d(double x, double y) { X = x; Y = y; }
  public Vector2d(double value) { X = Y = value; }

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

  public readonly double Length => Math.Sqrt(X * X + Y * Y);
  public readonly double LengthSquared => X * X + Y * Y;
  public readonly Vector2d PerpendicularRight => new(Y, -X);
  public readonly Vector2d PerpendicularLeft => new(-Y, X);
  public Vector2d Yx { readonly get => new(Y, X); set { Y = value.X; X = value.Y; } }

  public void Normalize() { double s = 1.0 / Length; X *= s; Y *= s; }
  public readonly Vector2d Normalized() { double s = 1.0 / Length; return new(X * s, Y * s); }
  public static Vector2d Normalize(Vector2d v) => v.Normalized();
  public static double Dot(Vector2d a, Vector2d b) => a.X * b.X + a.Y * b.Y;
  public static double Distance(Vector2d a, Vector2d b) => (a - b).Length;

  public static double DistanceSquared(Vector2d a, Vector2d b) => (a - b).LengthSquared;

  public static void Distance(in Vector2d a, in Vector2d b, out double result) => result = Distance(a, b);

  public static void DistanceSquared(in Vector2d a, in Vector2d b, out double result) => result = DistanceSquared(a, b);
  public static Vector2d Lerp(Vector2d a, Vector2d b, double t) => a + (b - a) * t;
  public static Vector2d ComponentMin(Vector2d a, Vector2d b) => new(Math.Min(a.X, b.X), Math.Min(a.Y, b.Y));
  public static Vector2d ComponentMax(Vector2d a, Vector2d b) => new(Math.Max(a.X, b.X), Math.Max(a.Y, b.Y));

  public static Vector2d operator +(Vector2d a, Vector2d b) => new(a.X + b.X, a.Y + b.Y);
  public static Vector2d operator -(Vector2d a, Vector2d b) => new(a.X - b.X, a.Y - b.Y);
  public static Vector2d operator -(Vector2d a) => new(-a.X, -a.Y);
  public static Vector2d operator *(Vector2d a, double s) => new(a.X * s, a.Y * s);
  public static Vector2d operator *(double s, Vector2d a) => new(a.X * s, a.Y * s);
  public static Vector2d operator *(Vector2d a, Vector2d b) => new(a.X * b.X, a.Y * b.Y);
  public static Vector2d operator /(Vector2d a, double s) => new(a.X / s, a.Y / s);
  public static bool operator ==(Vector2d a, Vector2d b) => a.Equals(b);
  public static bool operator !=(Vector2d a, Vector2d b) => !a.Equals(b);

  public readonly void Deconstruct(out double x, out double y) { x = X; y = Y; }
  public readonly bool Equals(Vector2d other) => X == other.X && Y == other.Y;
  public override readonly bool Equals(object? obj) => obj is Vector2d v && Equals(v);
  public override readonly int GetHashCode() => HashCode.Combine(X, Y);
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "({0}, {1})", X, Y);
}
