using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>OpenTK 4's vector of 4 booleans: the result of the float vectors' component comparisons (<c>LessThan</c> …).</summary>
[Serializable]
public struct Vector4b : IEquatable<Vector4b>
{
  /// <summary>The components x, y, z and w.</summary>
  public bool X, Y, Z, W;

  /// <summary>The vector (true, false, false, false).</summary>
  public static readonly Vector4b UnitX = new(true, false, false, false);
  /// <summary>The vector (false, true, false, false).</summary>
  public static readonly Vector4b UnitY = new(false, true, false, false);
  /// <summary>The vector (false, false, true, false).</summary>
  public static readonly Vector4b UnitZ = new(false, false, true, false);
  /// <summary>The vector (false, false, false, true).</summary>
  public static readonly Vector4b UnitW = new(false, false, false, true);
  /// <summary>Every component true.</summary>
  public static readonly Vector4b True = new(true);
  /// <summary>Every component false.</summary>
  public static readonly Vector4b False = new(false);

  /// <summary>A vector with every component equal to <paramref name="value"/>.</summary>
  public Vector4b(bool value) { X = value; Y = value; Z = value; W = value; }
  /// <summary>The vector (x, y, z, w).</summary>
  public Vector4b(bool x, bool y, bool z, bool w) { X = x; Y = y; Z = z; W = w; }
  /// <summary>(xy.X, xy.Y, z, w); z and w are false unless given.</summary>
  public Vector4b(Vector2b xy, bool z = false, bool w = false) { X = xy.X; Y = xy.Y; Z = z; W = w; }
  /// <summary>(xyz.X, xyz.Y, xyz.Z, w); w is false unless given.</summary>
  public Vector4b(Vector3b xyz, bool w = false) { X = xyz.X; Y = xyz.Y; Z = xyz.Z; W = w; }
  /// <summary>A copy of <paramref name="v"/>.</summary>
  public Vector4b(Vector4b v) { X = v.X; Y = v.Y; Z = v.Z; W = v.W; }

  /// <summary>The component with index 0 (X), 1 (Y), 2 (Z) or 3 (W); any other index throws
  /// <see cref="System.IndexOutOfRangeException"/>.</summary>
  public bool this[int index]
  {
    readonly get => index switch { 0 => X, 1 => Y, 2 => Z, 3 => W, _ => throw new IndexOutOfRangeException($"Vector4b index {index} is outside 0..3.") };
    set
    {
      switch (index)
      {
        case 0: X = value; break;
        case 1: Y = value; break;
        case 2: Z = value; break;
        case 3: W = value; break;
        default: throw new IndexOutOfRangeException($"Vector4b index {index} is outside 0..3.");
      }
    }
  }

  /// <summary>The vector with every component negated.</summary>
  public readonly Vector4b Not() => !this;
  /// <summary>Whether every component is true.</summary>
  public readonly bool All() => X && Y && Z && W;
  /// <summary>Whether at least one component is true.</summary>
  public readonly bool Any() => X || Y || Z || W;
  /// <summary>Whether every component of <paramref name="vector"/> is true.</summary>
  public static bool All(Vector4b vector) => vector.All();
  /// <summary>Whether at least one component of <paramref name="vector"/> is true.</summary>
  public static bool Any(Vector4b vector) => vector.Any();
  /// <summary>The vector with every component negated.</summary>
  public static Vector4b Not(Vector4b vec) => !vec;
  /// <summary>The component-wise logical and.</summary>
  public static Vector4b And(Vector4b left, Vector4b right) => left & right;
  /// <summary>The component-wise logical or.</summary>
  public static Vector4b Or(Vector4b left, Vector4b right) => left | right;
  /// <summary>The component-wise exclusive or.</summary>
  public static Vector4b Xor(Vector4b left, Vector4b right) => left ^ right;

  /// <summary>The components (x, y) as a Vector2b; setting assigns them to X, Y in the same order.</summary>
  public Vector2b Xy { readonly get => new(X, Y); set { X = value.X; Y = value.Y; } }
  /// <summary>The components (x, z) as a Vector2b; setting assigns them to X, Z in the same order.</summary>
  public Vector2b Xz { readonly get => new(X, Z); set { X = value.X; Z = value.Y; } }
  /// <summary>The components (x, w) as a Vector2b; setting assigns them to X, W in the same order.</summary>
  public Vector2b Xw { readonly get => new(X, W); set { X = value.X; W = value.Y; } }
  /// <summary>The components (y, x) as a Vector2b; setting assigns them to Y, X in the same order.</summary>
  public Vector2b Yx { readonly get => new(Y, X); set { Y = value.X; X = value.Y; } }
  /// <summary>The components (y, z) as a Vector2b; setting assigns them to Y, Z in the same order.</summary>
  public Vector2b Yz { readonly get => new(Y, Z); set { Y = value.X; Z = value.Y; } }
  /// <summary>The components (y, w) as a Vector2b; setting assigns them to Y, W in the same order.</summary>
  public Vector2b Yw { readonly get => new(Y, W); set { Y = value.X; W = value.Y; } }
  /// <summary>The components (z, x) as a Vector2b; setting assigns them to Z, X in the same order.</summary>
  public Vector2b Zx { readonly get => new(Z, X); set { Z = value.X; X = value.Y; } }
  /// <summary>The components (z, y) as a Vector2b; setting assigns them to Z, Y in the same order.</summary>
  public Vector2b Zy { readonly get => new(Z, Y); set { Z = value.X; Y = value.Y; } }
  /// <summary>The components (z, w) as a Vector2b; setting assigns them to Z, W in the same order.</summary>
  public Vector2b Zw { readonly get => new(Z, W); set { Z = value.X; W = value.Y; } }
  /// <summary>The components (w, x) as a Vector2b; setting assigns them to W, X in the same order.</summary>
  public Vector2b Wx { readonly get => new(W, X); set { W = value.X; X = value.Y; } }
  /// <summary>The components (w, y) as a Vector2b; setting assigns them to W, Y in the same order.</summary>
  public Vector2b Wy { readonly get => new(W, Y); set { W = value.X; Y = value.Y; } }
  /// <summary>The components (w, z) as a Vector2b; setting assigns them to W, Z in the same order.</summary>
  public Vector2b Wz { readonly get => new(W, Z); set { W = value.X; Z = value.Y; } }
  /// <summary>The components (x, y, z) as a Vector3b; setting assigns them to X, Y, Z in the same order.</summary>
  public Vector3b Xyz { readonly get => new(X, Y, Z); set { X = value.X; Y = value.Y; Z = value.Z; } }
  /// <summary>The components (x, y, w) as a Vector3b; setting assigns them to X, Y, W in the same order.</summary>
  public Vector3b Xyw { readonly get => new(X, Y, W); set { X = value.X; Y = value.Y; W = value.Z; } }
  /// <summary>The components (x, z, y) as a Vector3b; setting assigns them to X, Z, Y in the same order.</summary>
  public Vector3b Xzy { readonly get => new(X, Z, Y); set { X = value.X; Z = value.Y; Y = value.Z; } }
  /// <summary>The components (x, z, w) as a Vector3b; setting assigns them to X, Z, W in the same order.</summary>
  public Vector3b Xzw { readonly get => new(X, Z, W); set { X = value.X; Z = value.Y; W = value.Z; } }
  /// <summary>The components (x, w, y) as a Vector3b; setting assigns them to X, W, Y in the same order.</summary>
  public Vector3b Xwy { readonly get => new(X, W, Y); set { X = value.X; W = value.Y; Y = value.Z; } }
  /// <summary>The components (x, w, z) as a Vector3b; setting assigns them to X, W, Z in the same order.</summary>
  public Vector3b Xwz { readonly get => new(X, W, Z); set { X = value.X; W = value.Y; Z = value.Z; } }
  /// <summary>The components (y, x, z) as a Vector3b; setting assigns them to Y, X, Z in the same order.</summary>
  public Vector3b Yxz { readonly get => new(Y, X, Z); set { Y = value.X; X = value.Y; Z = value.Z; } }
  /// <summary>The components (y, x, w) as a Vector3b; setting assigns them to Y, X, W in the same order.</summary>
  public Vector3b Yxw { readonly get => new(Y, X, W); set { Y = value.X; X = value.Y; W = value.Z; } }
  /// <summary>The components (y, z, x) as a Vector3b; setting assigns them to Y, Z, X in the same order.</summary>
  public Vector3b Yzx { readonly get => new(Y, Z, X); set { Y = value.X; Z = value.Y; X = value.Z; } }
  /// <summary>The components (y, z, w) as a Vector3b; setting assigns them to Y, Z, W in the same order.</summary>
  public Vector3b Yzw { readonly get => new(Y, Z, W); set { Y = value.X; Z = value.Y; W = value.Z; } }
  /// <summary>The components (y, w, x) as a Vector3b; setting assigns them to Y, W, X in the same order.</summary>
  public Vector3b Ywx { readonly get => new(Y, W, X); set { Y = value.X; W = value.Y; X = value.Z; } }
  /// <summary>The components (y, w, z) as a Vector3b; setting assigns them to Y, W, Z in the same order.</summary>
  public Vector3b Ywz { readonly get => new(Y, W, Z); set { Y = value.X; W = value.Y; Z = value.Z; } }
  /// <summary>The components (z, x, y) as a Vector3b; setting assigns them to Z, X, Y in the same order.</summary>
  public Vector3b Zxy { readonly get => new(Z, X, Y); set { Z = value.X; X = value.Y; Y = value.Z; } }
  /// <summary>The components (z, x, w) as a Vector3b; setting assigns them to Z, X, W in the same order.</summary>
  public Vector3b Zxw { readonly get => new(Z, X, W); set { Z = value.X; X = value.Y; W = value.Z; } }
  /// <summary>The components (z, y, x) as a Vector3b; setting assigns them to Z, Y, X in the same order.</summary>
  public Vector3b Zyx { readonly get => new(Z, Y, X); set { Z = value.X; Y = value.Y; X = value.Z; } }
  /// <summary>The components (z, y, w) as a Vector3b; setting assigns them to Z, Y, W in the same order.</summary>
  public Vector3b Zyw { readonly get => new(Z, Y, W); set { Z = value.X; Y = value.Y; W = value.Z; } }
  /// <summary>The components (z, w, x) as a Vector3b; setting assigns them to Z, W, X in the same order.</summary>
  public Vector3b Zwx { readonly get => new(Z, W, X); set { Z = value.X; W = value.Y; X = value.Z; } }
  /// <summary>The components (z, w, y) as a Vector3b; setting assigns them to Z, W, Y in the same order.</summary>
  public Vector3b Zwy { readonly get => new(Z, W, Y); set { Z = value.X; W = value.Y; Y = value.Z; } }
  /// <summary>The components (w, x, y) as a Vector3b; setting assigns them to W, X, Y in the same order.</summary>
  public Vector3b Wxy { readonly get => new(W, X, Y); set { W = value.X; X = value.Y; Y = value.Z; } }
  /// <summary>The components (w, x, z) as a Vector3b; setting assigns them to W, X, Z in the same order.</summary>
  public Vector3b Wxz { readonly get => new(W, X, Z); set { W = value.X; X = value.Y; Z = value.Z; } }
  /// <summary>The components (w, y, x) as a Vector3b; setting assigns them to W, Y, X in the same order.</summary>
  public Vector3b Wyx { readonly get => new(W, Y, X); set { W = value.X; Y = value.Y; X = value.Z; } }
  /// <summary>The components (w, y, z) as a Vector3b; setting assigns them to W, Y, Z in the same order.</summary>
  public Vector3b Wyz { readonly get => new(W, Y, Z); set { W = value.X; Y = value.Y; Z = value.Z; } }
  /// <summary>The components (w, z, x) as a Vector3b; setting assigns them to W, Z, X in the same order.</summary>
  public Vector3b Wzx { readonly get => new(W, Z, X); set { W = value.X; Z = value.Y; X = value.Z; } }
  /// <summary>The components (w, z, y) as a Vector3b; setting assigns them to W, Z, Y in the same order.</summary>
  public Vector3b Wzy { readonly get => new(W, Z, Y); set { W = value.X; Z = value.Y; Y = value.Z; } }
  /// <summary>The components (x, y, w, z) as a Vector4b; setting assigns them to X, Y, W, Z in the same
  /// order.</summary>
  public Vector4b Xywz { readonly get => new(X, Y, W, Z); set { X = value.X; Y = value.Y; W = value.Z; Z = value.W; } }
  /// <summary>The components (x, z, y, w) as a Vector4b; setting assigns them to X, Z, Y, W in the same
  /// order.</summary>
  public Vector4b Xzyw { readonly get => new(X, Z, Y, W); set { X = value.X; Z = value.Y; Y = value.Z; W = value.W; } }
  /// <summary>The components (x, z, w, y) as a Vector4b; setting assigns them to X, Z, W, Y in the same
  /// order.</summary>
  public Vector4b Xzwy { readonly get => new(X, Z, W, Y); set { X = value.X; Z = value.Y; W = value.Z; Y = value.W; } }
  /// <summary>The components (x, w, y, z) as a Vector4b; setting assigns them to X, W, Y, Z in the same
  /// order.</summary>
  public Vector4b Xwyz { readonly get => new(X, W, Y, Z); set { X = value.X; W = value.Y; Y = value.Z; Z = value.W; } }
  /// <summary>The components (x, w, z, y) as a Vector4b; setting assigns them to X, W, Z, Y in the same
  /// order.</summary>
  public Vector4b Xwzy { readonly get => new(X, W, Z, Y); set { X = value.X; W = value.Y; Z = value.Z; Y = value.W; } }
  /// <summary>The components (y, x, z, w) as a Vector4b; setting assigns them to Y, X, Z, W in the same
  /// order.</summary>
  public Vector4b Yxzw { readonly get => new(Y, X, Z, W); set { Y = value.X; X = value.Y; Z = value.Z; W = value.W; } }
  /// <summary>The components (y, x, w, z) as a Vector4b; setting assigns them to Y, X, W, Z in the same
  /// order.</summary>
  public Vector4b Yxwz { readonly get => new(Y, X, W, Z); set { Y = value.X; X = value.Y; W = value.Z; Z = value.W; } }
  /// <summary>The components (y, z, x, w) as a Vector4b; setting assigns them to Y, Z, X, W in the same
  /// order.</summary>
  public Vector4b Yzxw { readonly get => new(Y, Z, X, W); set { Y = value.X; Z = value.Y; X = value.Z; W = value.W; } }
  /// <summary>The components (y, z, w, x) as a Vector4b; setting assigns them to Y, Z, W, X in the same
  /// order.</summary>
  public Vector4b Yzwx { readonly get => new(Y, Z, W, X); set { Y = value.X; Z = value.Y; W = value.Z; X = value.W; } }
  /// <summary>The components (y, w, x, z) as a Vector4b; setting assigns them to Y, W, X, Z in the same
  /// order.</summary>
  public Vector4b Ywxz { readonly get => new(Y, W, X, Z); set { Y = value.X; W = value.Y; X = value.Z; Z = value.W; } }
  /// <summary>The components (y, w, z, x) as a Vector4b; setting assigns them to Y, W, Z, X in the same
  /// order.</summary>
  public Vector4b Ywzx { readonly get => new(Y, W, Z, X); set { Y = value.X; W = value.Y; Z = value.Z; X = value.W; } }
  /// <summary>The components (z, x, y, w) as a Vector4b; setting assigns them to Z, X, Y, W in the same
  /// order.</summary>
  public Vector4b Zxyw { readonly get => new(Z, X, Y, W); set { Z = value.X; X = value.Y; Y = value.Z; W = value.W; } }
  /// <summary>The components (z, x, w, y) as a Vector4b; setting assigns them to Z, X, W, Y in the same
  /// order.</summary>
  public Vector4b Zxwy { readonly get => new(Z, X, W, Y); set { Z = value.X; X = value.Y; W = value.Z; Y = value.W; } }
  /// <summary>The components (z, y, x, w) as a Vector4b; setting assigns them to Z, Y, X, W in the same
  /// order.</summary>
  public Vector4b Zyxw { readonly get => new(Z, Y, X, W); set { Z = value.X; Y = value.Y; X = value.Z; W = value.W; } }
  /// <summary>The components (z, y, w, x) as a Vector4b; setting assigns them to Z, Y, W, X in the same
  /// order.</summary>
  public Vector4b Zywx { readonly get => new(Z, Y, W, X); set { Z = value.X; Y = value.Y; W = value.Z; X = value.W; } }
  /// <summary>The components (z, w, x, y) as a Vector4b; setting assigns them to Z, W, X, Y in the same
  /// order.</summary>
  public Vector4b Zwxy { readonly get => new(Z, W, X, Y); set { Z = value.X; W = value.Y; X = value.Z; Y = value.W; } }
  /// <summary>The components (z, w, y, x) as a Vector4b; setting assigns them to Z, W, Y, X in the same
  /// order.</summary>
  public Vector4b Zwyx { readonly get => new(Z, W, Y, X); set { Z = value.X; W = value.Y; Y = value.Z; X = value.W; } }
  /// <summary>The components (w, x, y, z) as a Vector4b; setting assigns them to W, X, Y, Z in the same
  /// order.</summary>
  public Vector4b Wxyz { readonly get => new(W, X, Y, Z); set { W = value.X; X = value.Y; Y = value.Z; Z = value.W; } }
  /// <summary>The components (w, x, z, y) as a Vector4b; setting assigns them to W, X, Z, Y in the same
  /// order.</summary>
  public Vector4b Wxzy { readonly get => new(W, X, Z, Y); set { W = value.X; X = value.Y; Z = value.Z; Y = value.W; } }
  /// <summary>The components (w, y, x, z) as a Vector4b; setting assigns them to W, Y, X, Z in the same
  /// order.</summary>
  public Vector4b Wyxz { readonly get => new(W, Y, X, Z); set { W = value.X; Y = value.Y; X = value.Z; Z = value.W; } }
  /// <summary>The components (w, y, z, x) as a Vector4b; setting assigns them to W, Y, Z, X in the same
  /// order.</summary>
  public Vector4b Wyzx { readonly get => new(W, Y, Z, X); set { W = value.X; Y = value.Y; Z = value.Z; X = value.W; } }
  /// <summary>The components (w, z, x, y) as a Vector4b; setting assigns them to W, Z, X, Y in the same
  /// order.</summary>
  public Vector4b Wzxy { readonly get => new(W, Z, X, Y); set { W = value.X; Z = value.Y; X = value.Z; Y = value.W; } }
  /// <summary>The components (w, z, y, x) as a Vector4b; setting assigns them to W, Z, Y, X in the same
  /// order.</summary>
  public Vector4b Wzyx { readonly get => new(W, Z, Y, X); set { W = value.X; Z = value.Y; Y = value.Z; X = value.W; } }

  /// <summary>The vector with every component negated.</summary>
  public static Vector4b operator !(Vector4b v) => new(!v.X, !v.Y, !v.Z, !v.W);
  /// <summary>The component-wise logical and.</summary>
  public static Vector4b operator &(Vector4b left, Vector4b right) => new(left.X & right.X, left.Y & right.Y, left.Z & right.Z, left.W & right.W);
  /// <summary>The component-wise logical or.</summary>
  public static Vector4b operator |(Vector4b left, Vector4b right) => new(left.X | right.X, left.Y | right.Y, left.Z | right.Z, left.W | right.W);
  /// <summary>The component-wise exclusive or.</summary>
  public static Vector4b operator ^(Vector4b left, Vector4b right) => new(left.X ^ right.X, left.Y ^ right.Y, left.Z ^ right.Z, left.W ^ right.W);
  /// <summary>Whether the two are equal, as <see cref="Equals(Vector4b)"/> compares them.</summary>
  public static bool operator ==(Vector4b left, Vector4b right) => left.Equals(right);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Vector4b)"/>.</summary>
  public static bool operator !=(Vector4b left, Vector4b right) => !left.Equals(right);
  /// <summary>The vector of a tuple, for <c>Vector4b v = (true, false, true, false);</c>.</summary>
  public static implicit operator Vector4b((bool X, bool Y, bool Z, bool W) values) => new(values.X, values.Y, values.Z, values.W);
  /// <summary>1 for true, 0 for false.</summary>
  public static explicit operator Vector4(Vector4b v) => new(v.X ? 1f : 0f, v.Y ? 1f : 0f, v.Z ? 1f : 0f, v.W ? 1f : 0f);

  /// <summary>Splits the vector into its components, for <c>var (x, y, z, w) = v;</c>.</summary>
  public readonly void Deconstruct(out bool x, out bool y, out bool z, out bool w) { x = X; y = Y; z = Z; w = W; }
  /// <summary>Whether every component equals the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Vector4b other) => X == other.X && Y == other.Y && Z == other.Z && W == other.W;
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Vector4b v && Equals(v);
  /// <inheritdoc/>
  public override readonly int GetHashCode() => HashCode.Combine(X, Y, Z, W);
  /// <inheritdoc/>
  public override readonly string ToString() => ToString(CultureInfo.CurrentCulture);
  /// <summary>The components in parentheses, formatted with <paramref name="formatProvider"/> (each as True or
  /// False).</summary>
  public readonly string ToString(IFormatProvider formatProvider) => string.Format(formatProvider, "({0}, {1}, {2}, {3})", X, Y, Z, W);
}
