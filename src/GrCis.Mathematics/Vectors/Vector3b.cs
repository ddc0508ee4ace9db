using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>OpenTK 4's vector of 3 booleans: the result of the float vectors' component comparisons (<c>LessThan</c> …).</summary>
[Serializable]
public struct Vector3b : IEquatable<Vector3b>
{
  public bool X, Y, Z;

  public static readonly Vector3b UnitX = new(true, false, false);
  public static readonly Vector3b UnitY = new(false, true, false);
  public static readonly Vector3b UnitZ = new(false, false, true);
  public static readonly Vector3b True = new(true);
  public static readonly Vector3b False = new(false);

  public Vector3b(bool value) { X = value; Y = value; Z = value; }
  public Vector3b(bool x, bool y, bool z) { X = x; Y = y; Z = z; }
  public Vector3b(Vector2b xy, bool z = false) { X = xy.X; Y = xy.Y; Z = z; }
  public Vector3b(Vector3b v) { X = v.X; Y = v.Y; Z = v.Z; }
  /// <summary>The first 3 components of <paramref name="v"/>.</summary>
  public Vector3b(Vector4b v) { X = v.X; Y = v.Y; Z = v.Z; }

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

  public readonly Vector3b Not() => !this;
  public readonly bool All() => X && Y && Z;
  public readonly bool Any() => X || Y || Z;
  public static bool All(Vector3b vector) => vector.All();
  public static bool Any(Vector3b vector) => vector.Any();
  public static Vector3b Not(Vector3b vec) => !vec;
  public static Vector3b And(Vector3b left, Vector3b right) => left & right;
  public static Vector3b Or(Vector3b left, Vector3b right) => left | right;
  public static Vector3b Xor(Vector3b left, Vector3b right) => left ^ right;

  public Vector2b Xy { readonly get => new(X, Y); set { X = value.X; Y = value.Y; } }
  public Vector2b Xz { readonly get => new(X, Z); set { X = value.X; Z = value.Y; } }
  public Vector2b Yx { readonly get => new(Y, X); set { Y = value.X; X = value.Y; } }
  public Vector2b Yz { readonly get => new(Y, Z); set { Y = value.X; Z = value.Y; } }
  public Vector2b Zx { readonly get => new(Z, X); set { Z = value.X; X = value.Y; } }
  public Vector2b Zy { readonly get => new(Z, Y); set { Z = value.X; Y = value.Y; } }
  public Vector3b Xzy { readonly get => new(X, Z, Y); set { X = value.X; Z = value.Y; Y = value.Z; } }
  public Vector3b Yxz { readonly get => new(Y, X, Z); set { Y = value.X; X = value.Y; Z = value.Z; } }
  public Vector3b Yzx { readonly get => new(Y, Z, X); set { Y = value.X; Z = value.Y; X = value.Z; } }
  public Vector3b Zxy { readonly get => new(Z, X, Y); set { Z = value.X; X = value.Y; Y = value.Z; } }
  public Vector3b Zyx { readonly get => new(Z, Y, X); set { Z = value.X; Y = value.Y; X = value.Z; } }

  public static Vector3b operator !(Vector3b v) => new(!v.X, !v.Y, !v.Z);
  public static Vector3b operator &(Vector3b left, Vector3b right) => new(left.X & right.X, left.Y & right.Y, left.Z & right.Z);
  public static Vector3b operator |(Vector3b left, Vector3b right) => new(left.X | right.X, left.Y | right.Y, left.Z | right.Z);
  public static Vector3b operator ^(Vector3b left, Vector3b right) => new(left.X ^ right.X, left.Y ^ right.Y, left.Z ^ right.Z);
  public static bool operator ==(Vector3b left, Vector3b right) => left.Equals(right);
  public static bool operator !=(Vector3b left, Vector3b right) => !left.Equals(right);
  public static implicit operator Vector3b((bool X, bool Y, bool Z) values) => new(values.X, values.Y, values.Z);
  /// <summary>1 for true, 0 for false.</summary>
  public static explicit operator Vector3(Vector3b v) => new(v.X ? 1f : 0f, v.Y ? 1f : 0f, v.Z ? 1f : 0f);

  public readonly void Deconstruct(out bool x, out bool y, out bool z) { x = X; y = Y; z = Z; }
  public readonly bool Equals(Vector3b other) => X == other.X && Y == other.Y && Z == other.Z;
  public override readonly bool Equals(object? obj) => obj is Vector3b v && Equals(v);
  public override readonly int GetHashCode() => HashCode.Combine(X, Y, Z);
  public override readonly string ToString() => ToString(CultureInfo.CurrentCulture);
  public readonly string ToString(IFormatProvider formatProvider) => string.Format(formatProvider, "({0}, {1}, {2})", X, Y, Z);
}
