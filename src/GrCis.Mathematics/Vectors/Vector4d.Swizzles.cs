namespace OpenTK.Mathematics;

// OpenTK 3's swizzles of Vector4d not declared in Vector4d.cs: read in the name's order, assigned back to the same components.
public partial struct Vector4d
{
  public Vector2d Xz { readonly get => new(X, Z); set { X = value.X; Z = value.Y; } }
  public Vector2d Xw { readonly get => new(X, W); set { X = value.X; W = value.Y; } }
  public Vector2d Yx { readonly get => new(Y, X); set { Y = value.X; X = value.Y; } }
  public Vector2d Yz { readonly get => new(Y, Z); set { Y = value.X; Z = value.Y; } }
  public Vector2d Yw { readonly get => new(Y, W); set { Y = value.X; W = value.Y; } }
  public Vector2d Zx { readonly get => new(Z, X); set { Z = value.X; X = value.Y; } }
  public Vector2d Zy { readonly get => new(Z, Y); set { Z = value.X; Y = value.Y; } }
  public Vector2d Zw { readonly get => new(Z, W); set { Z = value.X; W = value.Y; } }
  public Vector2d Wx { readonly get => new(W, X); set { W = value.X; X = value.Y; } }
  public Vector2d Wy { readonly get => new(W, Y); set { W = value.X; Y = value.Y; } }
  public Vector2d Wz { readonly get => new(W, Z); set { W = value.X; Z = value.Y; } }
  public Vector3d Xyw { readonly get => new(X, Y, W); set { X = value.X; Y = value.Y; W = value.Z; } }
  public Vector3d Xzy { readonly get => new(X, Z, Y); set { X = value.X; Z = value.Y; Y = value.Z; } }
  public Vector3d Xzw { readonly get => new(X, Z, W); set { X = value.X; Z = value.Y; W = value.Z; } }
  public Vector3d Xwy { readonly get => new(X, W, Y); set { X = value.X; W = value.Y; Y = value.Z; } }
  public Vector3d Xwz { readonly get => new(X, W, Z); set { X = value.X; W = value.Y; Z = value.Z; } }
  public Vector3d Yxz { readonly get => new(Y, X, Z); set { Y = value.X; X = value.Y; Z = value.Z; } }
  public Vector3d Yxw { readonly get => new(Y, X, W); set { Y = value.X; X = value.Y; W = value.Z; } }
  public Vector3d Yzx { readonly get => new(Y, Z, X); set { Y = value.X; Z = value.Y; X = value.Z; } }
  public Vector3d Yzw { readonly get => new(Y, Z, W); set { Y = value.X; Z = value.Y; W = value.Z; } }
  public Vector3d Ywx { readonly get => new(Y, W, X); set { Y = value.X; W = value.Y; X = value.Z; } }
  public Vector3d Ywz { readonly get => new(Y, W, Z); set { Y = value.X; W = value.Y; Z = value.Z; } }
  public Vector3d Zxy { readonly get => new(Z, X, Y); set { Z = value.X; X = value.Y; Y = value.Z; } }
  public Vector3d Zxw { readonly get => new(Z, X, W); set { Z = value.X; X = value.Y; W = value.Z; } }
  public Vector3d Zyx { readonly get => new(Z, Y, X); set { Z = value.X; Y = value.Y; X = value.Z; } }
  public Vector3d Zyw { readonly get => new(Z, Y, W); set { Z = value.X; Y = value.Y; W = value.Z; } }
  public Vector3d Zwx { readonly get => new(Z, W, X); set { Z = value.X; W = value.Y; X = value.Z; } }
  public Vector3d Zwy { readonly get => new(Z, W, Y); set { Z = value.X; W = value.Y; Y = value.Z; } }
  public Vector3d Wxy { readonly get => new(W, X, Y); set { W = value.X; X = value.Y; Y = value.Z; } }
  public Vector3d Wxz { readonly get => new(W, X, Z); set { W = value.X; X = value.Y; Z = value.Z; } }
  public Vector3d Wyx { readonly get => new(W, Y, X); set { W = value.X; Y = value.Y; X = value.Z; } }
  public Vector3d Wyz { readonly get => new(W, Y, Z); set { W = value.X; Y = value.Y; Z = value.Z; } }
  public Vector3d Wzx { readonly get => new(W, Z, X); set { W = value.X; Z = value.Y; X = value.Z; } }
  public Vector3d Wzy { readonly get => new(W, Z, Y); set { W = value.X; Z = value.Y; Y = value.Z; } }
  public Vector4d Xywz { readonly get => new(X, Y, W, Z); set { X = value.X; Y = value.Y; W = value.Z; Z = value.W; } }
  public Vector4d Xzyw { readonly get => new(X, Z, Y, W); set { X = value.X; Z = value.Y; Y = value.Z; W = value.W; } }
  public Vector4d Xzwy { readonly get => new(X, Z, W, Y); set { X = value.X; Z = value.Y; W = value.Z; Y = value.W; } }
  public Vector4d Xwyz { readonly get => new(X, W, Y, Z); set { X = value.X; W = value.Y; Y = value.Z; Z = value.W; } }
  public Vector4d Xwzy { readonly get => new(X, W, Z, Y); set { X = value.X; W = value.Y; Z = value.Z; Y = value.W; } }
  public Vector4d Yxzw { readonly get => new(Y, X, Z, W); set { Y = value.X; X = value.Y; Z = value.Z; W = value.W; } }
  public Vector4d Yxwz { readonly get => new(Y, X, W, Z); set { Y = value.X; X = value.Y; W = value.Z; Z = value.W; } }
  public Vector4d Yzxw { readonly get => new(Y, Z, X, W); set { Y = value.X; Z = value.Y; X = value.Z; W = value.W; } }
  public Vector4d Yzwx { readonly get => new(Y, Z, W, X); set { Y = value.X; Z = value.Y; W = value.Z; X = value.W; } }
  public Vector4d Ywxz { readonly get => new(Y, W, X, Z); set { Y = value.X; W = value.Y; X = value.Z; Z = value.W; } }
  public Vector4d Ywzx { readonly get => new(Y, W, Z, X); set { Y = value.X; W = value.Y; Z = value.Z; X = value.W; } }
  public Vector4d Zxyw { readonly get => new(Z, X, Y, W); set { Z = value.X; X = value.Y; Y = value.Z; W = value.W; } }
  public Vector4d Zxwy { readonly get => new(Z, X, W, Y); set { Z = value.X; X = value.Y; W = value.Z; Y = value.W; } }
  public Vector4d Zyxw { readonly get => new(Z, Y, X, W); set { Z = value.X; Y = value.Y; X = value.Z; W = value.W; } }
  public Vector4d Zywx { readonly get => new(Z, Y, W, X); set { Z = value.X; Y = value.Y; W = value.Z; X = value.W; } }
  public Vector4d Zwxy { readonly get => new(Z, W, X, Y); set { Z = value.X; W = value.Y; X = value.Z; Y = value.W; } }
  public Vector4d Zwyx { readonly get => new(Z, W, Y, X); set { Z = value.X; W = value.Y; Y = value.Z; X = value.W; } }
  public Vector4d Wxyz { readonly get => new(W, X, Y, Z); set { W = value.X; X = value.Y; Y = value.Z; Z = value.W; } }
  public Vector4d Wxzy { readonly get => new(W, X, Z, Y); set { W = value.X; X = value.Y; Z = value.Z; Y = value.W; } }
  public Vector4d Wyxz { readonly get => new(W, Y, X, Z); set { W = value.X; Y = value.Y; X = value.Z; Z = value.W; } }
  public Vector4d Wyzx { readonly get => new(W, Y, Z, X); set { W = value.X; Y = value.Y; Z = value.Z; X = value.W; } }
  public Vector4d Wzxy { readonly get => new(W, Z, X, Y); set { W = value.X; Z = value.Y; X = value.Z; Y = value.W; } }
  public Vector4d Wzyx { readonly get => new(W, Z, Y, X); set { W = value.X; Z = value.Y; Y = value.Z; X = value.W; } }

  // Four OpenTK 3 swizzles repeat a component (typos for permutations). Kept as OpenTK has them: the getter
  // reads the letters named, the setter writes the first value to X and the others to the letters after the first.
  public Vector4d Yyzw { readonly get => new(Y, Y, Z, W); set { X = value.X; Y = value.Y; Z = value.Z; W = value.W; } }
  public Vector4d Yywz { readonly get => new(Y, Y, W, Z); set { X = value.X; Y = value.Y; W = value.Z; Z = value.W; } }
  public Vector4d Zwzy { readonly get => new(Z, W, Z, Y); set { X = value.X; W = value.Y; Z = value.Z; Y = value.W; } }
  public Vector4d Wzyw { readonly get => new(W, Z, Y, W); set { X = value.X; Z = value.Y; Y = value.Z; W = value.W; } }
}
