using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>Single-precision 2D vector (OpenTK's name).</summary>
[Serializable]
public struct Vector2 : IEquatable<Vector2>
{
  public float X, Y;

  public Vector2(float x, float y) { X = x; Y = y; }

  public readonly float Length => MathF.Sqrt(X * X + Y * Y);
  public static Vector2 operator +(Vector2 a, Vector2 b) => new(a.X + b.X, a.Y + b.Y);
  public static Vector2 operator -(Vector2 a, Vector2 b) => new(a.X - b.X, a.Y - b.Y);
  public static Vector2 operator *(Vector2 a, float s) => new(a.X * s, a.Y * s);
  public static bool operator ==(Vector2 a, Vector2 b) => a.Equals(b);
  public static bool operator !=(Vector2 a, Vector2 b) => !a.Equals(b);

  public readonly bool Equals(Vector2 other) => X == other.X && Y == other.Y;
  public override readonly bool Equals(object? obj) => obj is Vector2 v && Equals(v);
  public override readonly int GetHashCode() => HashCode.Combine(X, Y);
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "({0}, {1})", X, Y);
}
