using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>OpenTK 4's vector of 2 booleans: the result of the float vectors' component comparisons (<c>LessThan</c> …).</summary>
[Serializable]
public struct Vector2b : IEquatable<Vector2b>
{
  public bool X, Y;

  public static readonly Vector2b UnitX = new(true, false);
  public static readonly Vector2b UnitY = new(false, true);
  public static readonly Vector2b True = new(true);
  public static readonly Vector2b False = new(false);

  public Vector2b(bool value) { X = value; Y = value; }
  public Vector2b(bool x, bool y) { X = x; Y = y; }
  public Vector2b(Vector2b v) { X = v.X; Y = v.Y; }
  /// <summary>The first 2 components of <paramref name="v"/>.</summary>
  public Vector2b(Vector3b v) { X = v.X; Y = v.Y; }
  /// <summary>The first 2 components of <paramref name="v"/>.</summary>
  public Vector2b(Vector4b v) { X = v.X; Y = v.Y; }

  public bool this[int index]
  {
    readonly get => index switch { 0 => X, 1 => Y, _ => throw new IndexOutOfRangeException($"Vector2b index {index} is outside 0..1.") };
    set
    {
      switch (index)
      {
        case 0: X = value; break;
        case 1: Y = value; break;
        default: throw new IndexOutOfRangeException($"Vector2b index {index} is outside 0..1.");
      }
    }
  }

  public readonly Vector2b Not() => !this;
  public readonly bool All() => X && Y;
  public readonly bool Any() => X || Y;
  public static bool All(Vector2b vector) => vector.All();
  public static bool Any(Vector2b vector) => vector.Any();
  public static Vector2b Not(Vector2b vec) => !vec;
  public static Vector2b And(Vector2b left, Vector2b right) => left & right;
  public static Vector2b Or(Vector2b left, Vector2b right) => left | right;
  public static Vector2b Xor(Vector2b left, Vector2b right) => left ^ right;

  public Vector2b Yx { readonly get => new(Y, X); set { Y = value.X; X = value.Y; } }

  public static Vector2b operator !(Vector2b v) => new(!v.X, !v.Y);
  public static Vector2b operator &(Vector2b left, Vector2b right) => new(left.X & right.X, left.Y & right.Y);
  public static Vector2b operator |(Vector2b left, Vector2b right) => new(left.X | right.X, left.Y | right.Y);
  public static Vector2b operator ^(Vector2b left, Vector2b right) => new(left.X ^ right.X, left.Y ^ right.Y);
  public static bool operator ==(Vector2b left, Vector2b right) => left.Equals(right);
  public static bool operator !=(Vector2b left, Vector2b right) => !left.Equals(right);
  public static implicit operator Vector2b((bool X, bool Y) values) => new(values.X, values.Y);
  /// <summary>1 for true, 0 for false.</summary>
  public static explicit operator Vector2(Vector2b v) => new(v.X ? 1f : 0f, v.Y ? 1f : 0f);

  public readonly void Deconstruct(out bool x, out bool y) { x = X; y = Y; }
  public readonly bool Equals(Vector2b other) => X == other.X && Y == other.Y;
  public override readonly bool Equals(object? obj) => obj is Vector2b v && Equals(v);
  public override readonly int GetHashCode() => HashCode.Combine(X, Y);
  public override readonly string ToString() => ToString(CultureInfo.CurrentCulture);
  public readonly string ToString(IFormatProvider formatProvider) => string.Format(formatProvider, "({0}, {1})", X, Y);
}
