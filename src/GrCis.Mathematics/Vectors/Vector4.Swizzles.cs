namespace OpenTK.Mathematics;

// OpenTK 3's swizzles of Vector4: read in the name's order, assigned back to the same components.
public partial struct Vector4
{
  public Vector2 Xy { readonly get => new(X, Y); set { X = value.X; Y = value.Y; } }
  public Vector2 Xz { readonly get => new(X, Z); set { X = value.X; Z = value.Y; } }
  public Vector2 Xw { readonly get => new(X, W); set { X = value.X; W = value.Y; } }
  public Vector2 Yx { readonly get => new(Y, X); set { Y = value.X; X = value.Y; } }
  public Vector2 Yz { readonly get => new(Y, Z); set { Y = value.X; Z = value.Y; } }
  public Vector2 Yw { readonly get => new(Y, W); set { Y = value.X; W = value.Y; } }
  public Vector2 Zx { readonly get => new(Z, X); set { Z = value.X; X = value.Y; } }
  public Vector2 Zy { readonly get => new(Z, Y); set { Z = value.X; Y = value.Y; } }
  public Vector2 Zw { readonly get => new(Z, W); set { Z = value.X; W = value.Y; } }
  public Vector2 Wx { readonly get => new(W, X); set { W = value.X; X = value.Y; } }
  public Vector2 Wy { readonly get => new(W, Y); set { W = value.X; Y = value.Y; } }
  public Vector2 Wz { readonly get => new(W, Z); set { W = value.X; Z = value.Y; } }
  public Vector3 Xyw { readonly get => new(X, Y, W); set { X = value.X; Y = value.Y; W = value.Z; } }
  public Vector3 Xzy { readonly get => new(X, Z, Y); set { X = value.X; Z = value.Y; Y = value.Z; } }
  public Vector3 Xzw { readonly get => new(X, Z, W); set { X = value.X; Z = value.Y; W = value.Z; } }
  public Vector3 Xwy { readonly get => new(X, W, Y); set { X = value.X; W = value.Y; Y = value.Z; } }
  public Vector3 Xwz { readonly get => new(X, W, Z); set { X = value.X; W = value.Y; Z = value.Z; } }
  public Vector3 Yxz { readonly get => new(Y, X, Z); set { Y = value.X; X = value.Y; Z = value.Z; } }
  public Vector3 Yxw { readonly get => new(Y, X, W); set { Y = value.X; X = value.Y; W = value.Z; } }
  public Vector3 Yzx { readonly get => new(Y, Z, X); set { Y = value.X; Z = value.Y; X = value.Z; } }
  public Vector3 Yzw { readonly get => new(Y, Z, W); set { Y = value.X; Z = value.Y; W = value.Z; } }
  public Vector3 Ywx { readonly get => new(Y, W, X); set { Y = value.X; W = value.Y; X = value.Z; } }
  public Vector3 Ywz { readonly get => new(Y, W, Z); set { Y = value.X; W = value.Y; Z = value.Z; } }
  public Vector3 Zxy { readonly get => new(Z, X, Y); set { Z = value.X; X = value.Y; Y = value.Z; } }
  public Vector3 Zxw { readonly get => new(Z, X, W); set { Z = value.X; X = value.Y; W = value.Z; } }
  public Vector3 Zyx { readonly get => new(Z, Y, X); set { Z = value.X; Y = value.Y; X = value.Z; } }
  public Vector3 Zyw { readonly get => new(Z, Y, W); set { Z = value.X; Y = value.Y; W = value.Z; } }
  public Vector3 Zwx { readonly get => new(Z, W, X); set { Z = value.X; W = value.Y; X = value.Z; } }
  public Vector3 Zwy { readonly get => new(Z, W, Y); set { Z = value.X; W = value.Y; Y = value.Z; } }
  public Vector3 Wxy { readonly get => new(W, X, Y); set { W = value.X; X = value.Y; Y = value.Z; } }
  public Vector3 Wxz { readonly get => new(W, X, Z); set { W = value.X; X = value.Y; Z = value.Z; } }
  public Vector3 Wyx { readonly get => new(W, Y, X); set { W = value.X; Y = value.Y; X = value.Z; } }
  public Vector3 Wyz { readonly get => new(W, Y, Z); set { W = value.X; Y = value.Y; Z = value.Z; } }
  public Vector3 Wzx { readonly get => new(W, Z, X); set { W = value.X; Z = value.Y; X = value.Z; } }
  public Vector3 Wzy { readonly get => new(W, Z, Y); set { W = value.X; Z = value.Y; Y = value.Z; } }
  public Vector4 Xywz { readonly get => new(X, Y, W, Z); set { X = value.X; Y = value.Y; W = value.Z; Z = value.W; } }
  public Vector4 Xzyw { readonly get => new(X, Z, Y, W); set { X = value.X; Z = value.Y; Y = value.Z; W = value.W; } }
  public Vector4 Xzwy { readonly get => new(X, Z, W, Y); set { X = value.X; Z = value.Y; W = value.Z; Y = value.W; } }
  public Vector4 Xwyz { readonly get => new(X, W, Y, Z); set { X = value.X; W = value.Y; Y = value.Z; Z = value.W; } }
  public Vector4 Xwzy { readonly get => new(X, W, Z, Y); set { X = value.X; W = value.Y; Z = value.Z; Y = value.W; } }
  public Vector4 Yxzw { readonly get => new(Y, X, Z, W); set { Y = value.X; X = value.Y; Z = value.Z; W = value.W; } }
  public Vector4 Yxwz { readonly get => new(Y, X, W, Z); set { Y = value.X; X = value.Y; W = value.Z; Z = value.W; } }
  public Vector4 Yzxw { readonly get => new(Y, Z, X, W); set { Y = value.X; Z = value.Y; X = value.Z; W = value.W; } }
  public Vector4 Yzwx { readonly get => new(Y, Z, W, X); set { Y = value.X; Z = value.Y; W = value.Z; X = value.W; } }
  public Vector4 Ywxz { readonly get => new(Y, W, X, Z); set { Y = value.X; W = value.Y; X = value.Z; Z = value.W; } }
  public Vector4 Ywzx { readonly get => new(Y, W, Z, X); set { Y = value.X; W = value.Y; Z = value.Z; X = value.W; } }
  public Vector4 Zxyw { readonly get => new(Z, X, Y, W); set { Z = value.X; X = value.Y; Y = value.Z; W = value.W; } }
  public Vector4 Zxwy { readonly get => new(Z, X, W, Y); set { Z = value.X; X = value.Y; W = value.Z; Y = value.W; } }
  public Vector4 Zyxw { readonly get => new(Z, Y, X, W); set { Z = value.X; Y = value.Y; X = value.Z; W = value.W; } }
  public Vector4 Zywx { readonly get => new(Z, Y, W, X); set { Z = value.X; Y = value.Y; W = value.Z; X = value.W; } }
  public Vector4 Zwxy { readonly get => new(Z, W, X, Y); set { Z = value.X; W = value.Y; X = value.Z; Y = value.W; } }
  public Vector4 Zwyx { readonly get => new(Z, W, Y, X); set { Z = value.X; W = value.Y; Y = value.Z; X = value.W; } }
  public Vector4 Wxyz { readonly get => new(W, X, Y, Z); set { W = value.X; X = value.Y; Y = value.Z; Z = value.W; } }
  public Vector4 Wxzy { readonly get => new(W, X, Z, Y); set { W = value.X; X = value.Y; Z = value.Z; Y = value.W; } }
  public Vector4 Wyxz { readonly get => new(W, Y, X, Z); set { W = value.X; Y = value.Y; X = value.Z; Z = value.W; } }
  public Vector4 Wyzx { readonly get => new(W, Y, Z, X); set { W = value.X; Y = value.Y; Z = value.Z; X = value.W; } }
  public Vector4 Wzxy { readonly get => new(W, Z, X, Y); set { W = value.X; Z = value.Y; X = value.Z; Y = value.W; } }
  public Vector4 Wzyx { readonly get => new(W, Z, Y, X); set { W = value.X; Z = value.Y; Y = value.Z; X = value.W; } }

  // Four OpenTK 3 swizzles repeat a component (typos for permutations). Kept as OpenTK has them: the getter
  // reads the letters named, the setter writes the first value to X and the others to the letters after the first.
  public Vector4 Yyzw { readonly get => new(Y, Y, Z, W); set { X = value.X; Y = value.Y; Z = value.Z; W = value.W; } }
  public Vector4 Yywz { readonly get => new(Y, Y, W, Z); set { X = value.X; Y = value.Y; W = value.Z; Z = value.W; } }
  public Vector4 Zwzy { readonly get => new(Z, W, Z, Y); set { X = value.X; W = value.Y; Z = value.Z; Y = value.W; } }
  public Vector4 Wzyw { readonly get => new(W, Z, Y, W); set { X = value.X; Z = value.Y; Y = value.Z; W = value.W; } }
}
