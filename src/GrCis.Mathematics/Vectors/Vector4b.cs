using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>OpenTK 4's vector of 4 booleans: the result of the float vectors' component comparisons (<c>LessThan</c> …).</summary>
[Serializable]
public struct Vector4b : IEquatable<Vector4b>
{
  public bool X, Y, Z, W;

  public static readonly Vector4b UnitX = new(true, false, false, false);
  public static readonly Vector4b UnitY = new(false, true, false, false);
  public static readonly Vector4b UnitZ = new(false, false, true, false);
  public static readonly Vector4b UnitW = new(false, false, false, true);
  public static readonly Vector4b True = new(true);
  public static readonly Vector4b False = new(false);

  public Vector4b(bool value) { X = value; Y = value; Z = value; W = value; }
  public Vector4b(bool x, bool y, bool z, bool w) { X = x; Y = y; Z = z; W = w; }
  public Vector4b(Vector2b xy, bool z = false, bool w = false) { X = xy.X; Y = xy.Y; Z = z; W = w; }
  public Vector4b(Vector3b xyz, bool w = false) { X = xyz.X; Y = xyz.Y; Z = xyz.Z; W = w; }
  public Vector4b(Vector4b v) { X = v.X; Y = v.Y; Z = v.Z; W = v.W; }

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

  public readonly Vector4b Not() => !this;
  public readonly bool All() => X && Y && Z && W;
  public readonly bool Any() => X || Y || Z || W;
  public static bool All(Vector4b vector) => vector.All();
  public static bool Any(Vector4b vector) => vector.Any();
  public static Vector4b Not(Vector4b vec) => !vec;
  public static Vector4b And(Vector4b left, Vector4b right) => left & right;
  public static Vector4b Or(Vector4b left, Vector4b right) => left | right;
  public static Vector4b Xor(Vector4b left, Vector4b right) => left ^ right;

  public Vector2b Xy { readonly get => new(X, Y); set { X = value.X; Y = value.Y; } }
  public Vector2b Xz { readonly get => new(X, Z); set { X = value.X; Z = value.Y; } }
  public Vector2b Xw { readonly get => new(X, W); set { X = value.X; W = value.Y; } }
  public Vector2b Yx { readonly get => new(Y, X); set { Y = value.X; X = value.Y; } }
  public Vector2b Yz { readonly get => new(Y, Z); set { Y = value.X; Z = value.Y; } }
  public Vector2b Yw { readonly get => new(Y, W); set { Y = value.X; W = value.Y; } }
  public Vector2b Zx { readonly get => new(Z, X); set { Z = value.X; X = value.Y; } }
  public Vector2b Zy { readonly get => new(Z, Y); set { Z = value.X; Y = value.Y; } }
  public Vector2b Zw { readonly get => new(Z, W); set { Z = value.X; W = value.Y; } }
  public Vector2b Wx { readonly get => new(W, X); set { W = value.X; X = value.Y; } }
  public Vector2b Wy { readonly get => new(W, Y); set { W = value.X; Y = value.Y; } }
  public Vector2b Wz { readonly get => new(W, Z); set { W = value.X; Z = value.Y; } }
  public Vector3b Xyz { readonly get => new(X, Y, Z); set { X = value.X; Y = value.Y; Z = value.Z; } }
  public Vector3b Xyw { readonly get => new(X, Y, W); set { X = value.X; Y = value.Y; W = value.Z; } }
  public Vector3b Xzy { readonly get => new(X, Z, Y); set { X = value.X; Z = value.Y; Y = value.Z; } }
  public Vector3b Xzw { readonly get => new(X, Z, W); set { X = value.X; Z = value.Y; W = value.Z; } }
  public Vector3b Xwy { readonly get => new(X, W, Y); set { X = value.X; W = value.Y; Y = value.Z; } }
  public Vector3b Xwz { readonly get => new(X, W, Z); set { X = value.X; W = value.Y; Z = value.Z; } }
  public Vector3b Yxz { readonly get => new(Y, X, Z); set { Y = value.X; X = value.Y; Z = value.Z; } }
  public Vector3b Yxw { readonly get => new(Y, X, W); set { Y = value.X; X = value.Y; W = value.Z; } }
  public Vector3b Yzx { readonly get => new(Y, Z, X); set { Y = value.X; Z = value.Y; X = value.Z; } }
  public Vector3b Yzw { readonly get => new(Y, Z, W); set { Y = value.X; Z = value.Y; W = value.Z; } }
  public Vector3b Ywx { readonly get => new(Y, W, X); set { Y = value.X; W = value.Y; X = value.Z; } }
  public Vector3b Ywz { readonly get => new(Y, W, Z); set { Y = value.X; W = value.Y; Z = value.Z; } }
  public Vector3b Zxy { readonly get => new(Z, X, Y); set { Z = value.X; X = value.Y; Y = value.Z; } }
  public Vector3b Zxw { readonly get => new(Z, X, W); set { Z = value.X; X = value.Y; W = value.Z; } }
  public Vector3b Zyx { readonly get => new(Z, Y, X); set { Z = value.X; Y = value.Y; X = value.Z; } }
  public Vector3b Zyw { readonly get => new(Z, Y, W); set { Z = value.X; Y = value.Y; W = value.Z; } }
  public Vector3b Zwx { readonly get => new(Z, W, X); set { Z = value.X; W = value.Y; X = value.Z; } }
  public Vector3b Zwy { readonly get => new(Z, W, Y); set { Z = value.X; W = value.Y; Y = value.Z; } }
  public Vector3b Wxy { readonly get => new(W, X, Y); set { W = value.X; X = value.Y; Y = value.Z; } }
  public Vector3b Wxz { readonly get => new(W, X, Z); set { W = value.X; X = value.Y; Z = value.Z; } }
  public Vector3b Wyx { readonly get => new(W, Y, X); set { W = value.X; Y = value.Y; X = value.Z; } }
  public Vector3b Wyz { readonly get => new(W, Y, Z); set { W = value.X; Y = value.Y; Z = value.Z; } }
  public Vector3b Wzx { readonly get => new(W, Z, X); set { W = value.X; Z = value.Y; X = value.Z; } }
  public Vector3b Wzy { readonly get => new(W, Z, Y); set { W = value.X; Z = value.Y; Y = value.Z; } }
  public Vector4b Xywz { readonly get => new(X, Y, W, Z); set { X = value.X; Y = value.Y; W = value.Z; Z = value.W; } }
  public Vector4b Xzyw { readonly get => new(X, Z, Y, W); set { X = value.X; Z = value.Y; Y = value.Z; W = value.W; } }
  public Vector4b Xzwy { readonly get => new(X, Z, W, Y); set { X = value.X; Z = value.Y; W = value.Z; Y = value.W; } }
  public Vector4b Xwyz { readonly get => new(X, W, Y, Z); set { X = value.X; W = value.Y; Y = value.Z; Z = value.W; } }
  public Vector4b Xwzy { readonly get => new(X, W, Z, Y); set { X = value.X; W = value.Y; Z = value.Z; Y = value.W; } }
  public Vector4b Yxzw { readonly get => new(Y, X, Z, W); set { Y = value.X; X = value.Y; Z = value.Z; W = value.W; } }
  public Vector4b Yxwz { readonly get => new(Y, X, W, Z); set { Y = value.X; X = value.Y; W = value.Z; Z = value.W; } }
  public Vector4b Yzxw { readonly get => new(Y, Z, X, W); set { Y = value.X; Z = value.Y; X = value.Z; W = value.W; } }
  public Vector4b Yzwx { readonly get => new(Y, Z, W, X); set { Y = value.X; Z = value.Y; W = value.Z; X = value.W; } }
  public Vector4b Ywxz { readonly get => new(Y, W, X, Z); set { Y = value.X; W = value.Y; X = value.Z; Z = value.W; } }
  public Vector4b Ywzx { readonly get => new(Y, W, Z, X); set { Y = value.X; W = value.Y; Z = value.Z; X = value.W; } }
  public Vector4b Zxyw { readonly get => new(Z, X, Y, W); set { Z = value.X; X = value.Y; Y = value.Z; W = value.W; } }
  public Vector4b Zxwy { readonly get => new(Z, X, W, Y); set { Z = value.X; X = value.Y; W = value.Z; Y = value.W; } }
  public Vector4b Zyxw { readonly get => new(Z, Y, X, W); set { Z = value.X; Y = value.Y; X = value.Z; W = value.W; } }
  public Vector4b Zywx { readonly get => new(Z, Y, W, X); set { Z = value.X; Y = value.Y; W = value.Z; X = value.W; } }
  public Vector4b Zwxy { readonly get => new(Z, W, X, Y); set { Z = value.X; W = value.Y; X = value.Z; Y = value.W; } }
  public Vector4b Zwyx { readonly get => new(Z, W, Y, X); set { Z = value.X; W = value.Y; Y = value.Z; X = value.W; } }
  public Vector4b Wxyz { readonly get => new(W, X, Y, Z); set { W = value.X; X = value.Y; Y = value.Z; Z = value.W; } }
  public Vector4b Wxzy { readonly get => new(W, X, Z, Y); set { W = value.X; X = value.Y; Z = value.Z; Y = value.W; } }
  public Vector4b Wyxz { readonly get => new(W, Y, X, Z); set { W = value.X; Y = value.Y; X = value.Z; Z = value.W; } }
  public Vector4b Wyzx { readonly get => new(W, Y, Z, X); set { W = value.X; Y = value.Y; Z = value.Z; X = value.W; } }
  public Vector4b Wzxy { readonly get => new(W, Z, X, Y); set { W = value.X; Z = value.Y; X = value.Z; Y = value.W; } }
  public Vector4b Wzyx { readonly get => new(W, Z, Y, X); set { W = value.X; Z = value.Y; Y = value.Z; X = value.W; } }

  public static Vector4b operator !(Vector4b v) => new(!v.X, !v.Y, !v.Z, !v.W);
  public static Vector4b operator &(Vector4b left, Vector4b right) => new(left.X & right.X, left.Y & right.Y, left.Z & right.Z, left.W & right.W);
  public static Vector4b operator |(Vector4b left, Vector4b right) => new(left.X | right.X, left.Y | right.Y, left.Z | right.Z, left.W | right.W);
  public static Vector4b operator ^(Vector4b left, Vector4b right) => new(left.X ^ right.X, left.Y ^ right.Y, left.Z ^ right.Z, left.W ^ right.W);
  public static bool operator ==(Vector4b left, Vector4b right) => left.Equals(right);
  public static bool operator !=(Vector4b left, Vector4b right) => !left.Equals(right);
  public static implicit operator Vector4b((bool X, bool Y, bool Z, bool W) values) => new(values.X, values.Y, values.Z, values.W);
  /// <summary>1 for true, 0 for false.</summary>
  public static explicit operator Vector4(Vector4b v) => new(v.X ? 1f : 0f, v.Y ? 1f : 0f, v.Z ? 1f : 0f, v.W ? 1f : 0f);

  public readonly void Deconstruct(out bool x, out bool y, out bool z, out bool w) { x = X; y = Y; z = Z; w = W; }
  public readonly bool Equals(Vector4b other) => X == other.X && Y == other.Y && Z == other.Z && W == other.W;
  public override readonly bool Equals(object? obj) => obj is Vector4b v && Equals(v);
  public override readonly int GetHashCode() => HashCode.Combine(X, Y, Z, W);
  public override readonly string ToString() => ToString(CultureInfo.CurrentCulture);
  public readonly string ToString(IFormatProvider formatProvider) => string.Format(formatProvider, "({0}, {1}, {2}, {3})", X, Y, Z, W);
}
