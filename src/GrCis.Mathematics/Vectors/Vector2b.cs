using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>OpenTK 4's vector of 2 booleans: the result of the float vectors' component comparisons (<c>LessThan</c> …).</summary>
[Serializable]
public struct Vector2b : IEquatable<Vector2b>
{
  /// <summary>The components x and y.</summary>
  public bool X, Y;

  /// <summary>The vector (true, false).</summary>
  public static readonly Vector2b UnitX = new(true, false);
  /// <summary>The vector (false, true).</summary>
  public static readonly Vector2b UnitY = new(false, true);
  /// <summary>Every component true.</summary>
  public static readonly Vector2b True = new(true);
  /// <summary>Every component false.</summary>
  public static readonly Vector2b False = new(false);

  /// <summary>A vector with every component equal to <paramref name="value"/>.</summary>
  public Vector2b(bool value) { X = value; Y = value; }
  /// <summary>The vector (x, y).</summary>
  public Vector2b(bool x, bool y) { X = x; Y = y; }
  /// <summary>A copy of <paramref name="v"/>.</summary>
  public Vector2b(Vector2b v) { X = v.X; Y = v.Y; }
  /// <summary>The first 2 components of <paramref name="v"/>.</summary>
  public Vector2b(Vector3b v) { X = v.X; Y = v.Y; }
  /// <summary>The first 2 components of <paramref name="v"/>.</summary>
  public Vector2b(Vector4b v) { X = v.X; Y = v.Y; }

  /// <summary>The component with index 0 (X) or 1 (Y); any other index throws
  /// <see cref="System.IndexOutOfRangeException"/>.</summary>
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

  /// <summary>The vector with every component negated.</summary>
  public readonly Vector2b Not() => !this;
  /// <summary>Whether every component is true.</summary>
  public readonly bool All() => X && Y;
  /// <summary>Whether at least one component is true.</summary>
  public readonly bool Any() => X || Y;
  /// <summary>Whether every component of <paramref name="vector"/> is true.</summary>
  public static bool All(Vector2b vector) => vector.All();
  /// <summary>Whether at least one component of <paramref name="vector"/> is true.</summary>
  public static bool Any(Vector2b vector) => vector.Any();
  /// <summary>The vector with every component negated.</summary>
  public static Vector2b Not(Vector2b vec) => !vec;
  /// <summary>The component-wise logical and.</summary>
  public static Vector2b And(Vector2b left, Vector2b right) => left & right;
  /// <summary>The component-wise logical or.</summary>
  public static Vector2b Or(Vector2b left, Vector2b right) => left | right;
  /// <summary>The component-wise exclusive or.</summary>
  public static Vector2b Xor(Vector2b left, Vector2b right) => left ^ right;

  /// <summary>The components (y, x) as a Vector2b; setting assigns them to Y, X in the same order.</summary>
  public Vector2b Yx { readonly get => new(Y, X); set { Y = value.X; X = value.Y; } }

  /// <summary>The vector with every component negated.</summary>
  public static Vector2b operator !(Vector2b v) => new(!v.X, !v.Y);
  /// <summary>The component-wise logical and.</summary>
  public static Vector2b operator &(Vector2b left, Vector2b right) => new(left.X & right.X, left.Y & right.Y);
  /// <summary>The component-wise logical or.</summary>
  public static Vector2b operator |(Vector2b left, Vector2b right) => new(left.X | right.X, left.Y | right.Y);
  /// <summary>The component-wise exclusive or.</summary>
  public static Vector2b operator ^(Vector2b left, Vector2b right) => new(left.X ^ right.X, left.Y ^ right.Y);
  /// <summary>Whether the two are equal, as <see cref="Equals(Vector2b)"/> compares them.</summary>
  public static bool operator ==(Vector2b left, Vector2b right) => left.Equals(right);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Vector2b)"/>.</summary>
  public static bool operator !=(Vector2b left, Vector2b right) => !left.Equals(right);
  /// <summary>The vector of a tuple, for <c>Vector2b v = (true, false);</c>.</summary>
  public static implicit operator Vector2b((bool X, bool Y) values) => new(values.X, values.Y);
  /// <summary>1 for true, 0 for false.</summary>
  public static explicit operator Vector2(Vector2b v) => new(v.X ? 1f : 0f, v.Y ? 1f : 0f);

  /// <summary>Splits the vector into its components, for <c>var (x, y) = v;</c>.</summary>
  public readonly void Deconstruct(out bool x, out bool y) { x = X; y = Y; }
  /// <summary>Whether every component equals the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Vector2b other) => X == other.X && Y == other.Y;
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Vector2b v && Equals(v);
  /// <inheritdoc/>
  public override readonly int GetHashCode() => HashCode.Combine(X, Y);
  /// <inheritdoc/>
  public override readonly string ToString() => ToString(CultureInfo.CurrentCulture);
  /// <summary>The components in parentheses, formatted with <paramref name="formatProvider"/> (each as True or
  /// False).</summary>
  public readonly string ToString(IFormatProvider formatProvider) => string.Format(formatProvider, "({0}, {1})", X, Y);
}
