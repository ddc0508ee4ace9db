using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>OpenTK 4's vector of 3 booleans: the result of the float vectors' component comparisons (<c>LessThan</c> …).</summary>
[Serializable]
public struct Vector3b : IEquatable<Vector3b>
{
  /// <summary>The components x, y and z.</summary>
  public bool X, Y, Z;

  /// <summary>The vector (true, false, false).</summary>
  public static readonly Vector3b UnitX = new(true, false, false);
  /// <summary>The vector (false, true, false).</summary>
  public static readonly Vector3b UnitY = new(false, true, false);
  /// <summary>The vector (false, false, true).</summary>
  public static readonly Vector3b UnitZ = new(false, false, true);
  /// <summary>Every component true.</summary>
  public static readonly Vector3b True = new(true);
  /// <summary>Every component false.</summary>
  public static readonly Vector3b False = new(false);

  /// <summary>A vector with every component equal to <paramref name="value"/>.</summary>
  public Vector3b(bool value) { X = value; Y = value; Z = value; }
  /// <summary>The vector (x, y, z).</summary>
  public Vector3b(bool x, bool y, bool z) { X = x; Y = y; Z = z; }
  /// <summary>(xy.X, xy.Y, z); z is false unless given.</summary>
  public Vector3b(Vector2b xy, bool z = false) { X = xy.X; Y = xy.Y; Z = z; }
  /// <summary>A copy of <paramref name="v"/>.</summary>
  public Vector3b(Vector3b v) { X = v.X; Y = v.Y; Z = v.Z; }
  /// <summary>The first 3 components of <paramref name="v"/>.</summary>
  public Vector3b(Vector4b v) { X = v.X; Y = v.Y; Z = v.Z; }

  /// <summary>The component with index 0 (X), 1 (Y) or 2 (Z); any other index throws
  /// <see cref="System.IndexOutOfRangeException"/>.</summary>
  public bool this[int index]
  {
    readonly get => index switch { 0 => X, 1 => Y, 2 => Z, _ => throw new IndexOutOfRangeException($"Vector3b index {index} is outside 0..2.") };
    set
    {
      switch (index)
      {
        case 0: X = value; break;
        case 1: Y = value; break;
        case 2: Z = value; break;
        default: throw new IndexOutOfRangeException($"Vector3b index {index} is outside 0..2.");
      }
    }
  }

  /// <summary>The vector with every component negated.</summary>
  public readonly Vector3b Not() => !this;
  /// <summary>Whether every component is true.</summary>
  public readonly bool All() => X && Y && Z;
  /// <summary>Whether at least one component is true.</summary>
  public readonly bool Any() => X || Y || Z;
  /// <summary>Whether every component of <paramref name="vector"/> is true.</summary>
  public static bool All(Vector3b vector) => vector.All();
  /// <summary>Whether at least one component of <paramref name="vector"/> is true.</summary>
  public static bool Any(Vector3b vector) => vector.Any();
  /// <summary>The vector with every component negated.</summary>
  public static Vector3b Not(Vector3b vec) => !vec;
  /// <summary>The component-wise logical and.</summary>
  public static Vector3b And(Vector3b left, Vector3b right) => left & right;
  /// <summary>The component-wise logical or.</summary>
  public static Vector3b Or(Vector3b left, Vector3b right) => left | right;
  /// <summary>The component-wise exclusive or.</summary>
  public static Vector3b Xor(Vector3b left, Vector3b right) => left ^ right;

  /// <summary>The components (x, y) as a Vector2b; setting assigns them to X, Y in the same order.</summary>
  public Vector2b Xy { readonly get => new(X, Y); set { X = value.X; Y = value.Y; } }
  /// <summary>The components (x, z) as a Vector2b; setting assigns them to X, Z in the same order.</summary>
  public Vector2b Xz { readonly get => new(X, Z); set { X = value.X; Z = value.Y; } }
  /// <summary>The components (y, x) as a Vector2b; setting assigns them to Y, X in the same order.</summary>
  public Vector2b Yx { readonly get => new(Y, X); set { Y = value.X; X = value.Y; } }
  /// <summary>The components (y, z) as a Vector2b; setting assigns them to Y, Z in the same order.</summary>
  public Vector2b Yz { readonly get => new(Y, Z); set { Y = value.X; Z = value.Y; } }
  /// <summary>The components (z, x) as a Vector2b; setting assigns them to Z, X in the same order.</summary>
  public Vector2b Zx { readonly get => new(Z, X); set { Z = value.X; X = value.Y; } }
  /// <summary>The components (z, y) as a Vector2b; setting assigns them to Z, Y in the same order.</summary>
  public Vector2b Zy { readonly get => new(Z, Y); set { Z = value.X; Y = value.Y; } }
  /// <summary>The components (x, z, y) as a Vector3b; setting assigns them to X, Z, Y in the same order.</summary>
  public Vector3b Xzy { readonly get => new(X, Z, Y); set { X = value.X; Z = value.Y; Y = value.Z; } }
  /// <summary>The components (y, x, z) as a Vector3b; setting assigns them to Y, X, Z in the same order.</summary>
  public Vector3b Yxz { readonly get => new(Y, X, Z); set { Y = value.X; X = value.Y; Z = value.Z; } }
  /// <summary>The components (y, z, x) as a Vector3b; setting assigns them to Y, Z, X in the same order.</summary>
  public Vector3b Yzx { readonly get => new(Y, Z, X); set { Y = value.X; Z = value.Y; X = value.Z; } }
  /// <summary>The components (z, x, y) as a Vector3b; setting assigns them to Z, X, Y in the same order.</summary>
  public Vector3b Zxy { readonly get => new(Z, X, Y); set { Z = value.X; X = value.Y; Y = value.Z; } }
  /// <summary>The components (z, y, x) as a Vector3b; setting assigns them to Z, Y, X in the same order.</summary>
  public Vector3b Zyx { readonly get => new(Z, Y, X); set { Z = value.X; Y = value.Y; X = value.Z; } }

  /// <summary>The vector with every component negated.</summary>
  public static Vector3b operator !(Vector3b v) => new(!v.X, !v.Y, !v.Z);
  /// <summary>The component-wise logical and.</summary>
  public static Vector3b operator &(Vector3b left, Vector3b right) => new(left.X & right.X, left.Y & right.Y, left.Z & right.Z);
  /// <summary>The component-wise logical or.</summary>
  public static Vector3b operator |(Vector3b left, Vector3b right) => new(left.X | right.X, left.Y | right.Y, left.Z | right.Z);
  /// <summary>The component-wise exclusive or.</summary>
  public static Vector3b operator ^(Vector3b left, Vector3b right) => new(left.X ^ right.X, left.Y ^ right.Y, left.Z ^ right.Z);
  /// <summary>Whether the two are equal, as <see cref="Equals(Vector3b)"/> compares them.</summary>
  public static bool operator ==(Vector3b left, Vector3b right) => left.Equals(right);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Vector3b)"/>.</summary>
  public static bool operator !=(Vector3b left, Vector3b right) => !left.Equals(right);
  /// <summary>The vector of a tuple, for <c>Vector3b v = (true, false, true);</c>.</summary>
  public static implicit operator Vector3b((bool X, bool Y, bool Z) values) => new(values.X, values.Y, values.Z);
  /// <summary>1 for true, 0 for false.</summary>
  public static explicit operator Vector3(Vector3b v) => new(v.X ? 1f : 0f, v.Y ? 1f : 0f, v.Z ? 1f : 0f);

  /// <summary>Splits the vector into its components, for <c>var (x, y, z) = v;</c>.</summary>
  public readonly void Deconstruct(out bool x, out bool y, out bool z) { x = X; y = Y; z = Z; }
  /// <summary>Whether every component equals the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Vector3b other) => X == other.X && Y == other.Y && Z == other.Z;
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Vector3b v && Equals(v);
  /// <inheritdoc/>
  public override readonly int GetHashCode() => HashCode.Combine(X, Y, Z);
  /// <inheritdoc/>
  public override readonly string ToString() => ToString(CultureInfo.CurrentCulture);
  /// <summary>The components in parentheses, formatted with <paramref name="formatProvider"/> (each as True or
  /// False).</summary>
  public readonly string ToString(IFormatProvider formatProvider) => string.Format(formatProvider, "({0}, {1}, {2})", X, Y, Z);
}
