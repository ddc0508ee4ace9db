namespace OpenTK.Mathematics;

// OpenTK 3's swizzles of Vector4d not declared in Vector4d.cs: read in the name's order, assigned back to the same components.
public partial struct Vector4d
{
  /// <summary>The components (x, z) as a Vector2d; setting assigns them to X, Z in the same order.</summary>
  public Vector2d Xz { readonly get => new(X, Z); set { X = value.X; Z = value.Y; } }
  /// <summary>The components (x, w) as a Vector2d; setting assigns them to X, W in the same order.</summary>
  public Vector2d Xw { readonly get => new(X, W); set { X = value.X; W = value.Y; } }
  /// <summary>The components (y, x) as a Vector2d; setting assigns them to Y, X in the same order.</summary>
  public Vector2d Yx { readonly get => new(Y, X); set { Y = value.X; X = value.Y; } }
  /// <summary>The components (y, z) as a Vector2d; setting assigns them to Y, Z in the same order.</summary>
  public Vector2d Yz { readonly get => new(Y, Z); set { Y = value.X; Z = value.Y; } }
  /// <summary>The components (y, w) as a Vector2d; setting assigns them to Y, W in the same order.</summary>
  public Vector2d Yw { readonly get => new(Y, W); set { Y = value.X; W = value.Y; } }
  /// <summary>The components (z, x) as a Vector2d; setting assigns them to Z, X in the same order.</summary>
  public Vector2d Zx { readonly get => new(Z, X); set { Z = value.X; X = value.Y; } }
  /// <summary>The components (z, y) as a Vector2d; setting assigns them to Z, Y in the same order.</summary>
  public Vector2d Zy { readonly get => new(Z, Y); set { Z = value.X; Y = value.Y; } }
  /// <summary>The components (z, w) as a Vector2d; setting assigns them to Z, W in the same order.</summary>
  public Vector2d Zw { readonly get => new(Z, W); set { Z = value.X; W = value.Y; } }
  /// <summary>The components (w, x) as a Vector2d; setting assigns them to W, X in the same order.</summary>
  public Vector2d Wx { readonly get => new(W, X); set { W = value.X; X = value.Y; } }
  /// <summary>The components (w, y) as a Vector2d; setting assigns them to W, Y in the same order.</summary>
  public Vector2d Wy { readonly get => new(W, Y); set { W = value.X; Y = value.Y; } }
  /// <summary>The components (w, z) as a Vector2d; setting assigns them to W, Z in the same order.</summary>
  public Vector2d Wz { readonly get => new(W, Z); set { W = value.X; Z = value.Y; } }
  /// <summary>The components (x, y, w) as a Vector3d; setting assigns them to X, Y, W in the same order.</summary>
  public Vector3d Xyw { readonly get => new(X, Y, W); set { X = value.X; Y = value.Y; W = value.Z; } }
  /// <summary>The components (x, z, y) as a Vector3d; setting assigns them to X, Z, Y in the same order.</summary>
  public Vector3d Xzy { readonly get => new(X, Z, Y); set { X = value.X; Z = value.Y; Y = value.Z; } }
  /// <summary>The components (x, z, w) as a Vector3d; setting assigns them to X, Z, W in the same order.</summary>
  public Vector3d Xzw { readonly get => new(X, Z, W); set { X = value.X; Z = value.Y; W = value.Z; } }
  /// <summary>The components (x, w, y) as a Vector3d; setting assigns them to X, W, Y in the same order.</summary>
  public Vector3d Xwy { readonly get => new(X, W, Y); set { X = value.X; W = value.Y; Y = value.Z; } }
  /// <summary>The components (x, w, z) as a Vector3d; setting assigns them to X, W, Z in the same order.</summary>
  public Vector3d Xwz { readonly get => new(X, W, Z); set { X = value.X; W = value.Y; Z = value.Z; } }
  /// <summary>The components (y, x, z) as a Vector3d; setting assigns them to Y, X, Z in the same order.</summary>
  public Vector3d Yxz { readonly get => new(Y, X, Z); set { Y = value.X; X = value.Y; Z = value.Z; } }
  /// <summary>The components (y, x, w) as a Vector3d; setting assigns them to Y, X, W in the same order.</summary>
  public Vector3d Yxw { readonly get => new(Y, X, W); set { Y = value.X; X = value.Y; W = value.Z; } }
  /// <summary>The components (y, z, x) as a Vector3d; setting assigns them to Y, Z, X in the same order.</summary>
  public Vector3d Yzx { readonly get => new(Y, Z, X); set { Y = value.X; Z = value.Y; X = value.Z; } }
  /// <summary>The components (y, z, w) as a Vector3d; setting assigns them to Y, Z, W in the same order.</summary>
  public Vector3d Yzw { readonly get => new(Y, Z, W); set { Y = value.X; Z = value.Y; W = value.Z; } }
  /// <summary>The components (y, w, x) as a Vector3d; setting assigns them to Y, W, X in the same order.</summary>
  public Vector3d Ywx { readonly get => new(Y, W, X); set { Y = value.X; W = value.Y; X = value.Z; } }
  /// <summary>The components (y, w, z) as a Vector3d; setting assigns them to Y, W, Z in the same order.</summary>
  public Vector3d Ywz { readonly get => new(Y, W, Z); set { Y = value.X; W = value.Y; Z = value.Z; } }
  /// <summary>The components (z, x, y) as a Vector3d; setting assigns them to Z, X, Y in the same order.</summary>
  public Vector3d Zxy { readonly get => new(Z, X, Y); set { Z = value.X; X = value.Y; Y = value.Z; } }
  /// <summary>The components (z, x, w) as a Vector3d; setting assigns them to Z, X, W in the same order.</summary>
  public Vector3d Zxw { readonly get => new(Z, X, W); set { Z = value.X; X = value.Y; W = value.Z; } }
  /// <summary>The components (z, y, x) as a Vector3d; setting assigns them to Z, Y, X in the same order.</summary>
  public Vector3d Zyx { readonly get => new(Z, Y, X); set { Z = value.X; Y = value.Y; X = value.Z; } }
  /// <summary>The components (z, y, w) as a Vector3d; setting assigns them to Z, Y, W in the same order.</summary>
  public Vector3d Zyw { readonly get => new(Z, Y, W); set { Z = value.X; Y = value.Y; W = value.Z; } }
  /// <summary>The components (z, w, x) as a Vector3d; setting assigns them to Z, W, X in the same order.</summary>
  public Vector3d Zwx { readonly get => new(Z, W, X); set { Z = value.X; W = value.Y; X = value.Z; } }
  /// <summary>The components (z, w, y) as a Vector3d; setting assigns them to Z, W, Y in the same order.</summary>
  public Vector3d Zwy { readonly get => new(Z, W, Y); set { Z = value.X; W = value.Y; Y = value.Z; } }
  /// <summary>The components (w, x, y) as a Vector3d; setting assigns them to W, X, Y in the same order.</summary>
  public Vector3d Wxy { readonly get => new(W, X, Y); set { W = value.X; X = value.Y; Y = value.Z; } }
  /// <summary>The components (w, x, z) as a Vector3d; setting assigns them to W, X, Z in the same order.</summary>
  public Vector3d Wxz { readonly get => new(W, X, Z); set { W = value.X; X = value.Y; Z = value.Z; } }
  /// <summary>The components (w, y, x) as a Vector3d; setting assigns them to W, Y, X in the same order.</summary>
  public Vector3d Wyx { readonly get => new(W, Y, X); set { W = value.X; Y = value.Y; X = value.Z; } }
  /// <summary>The components (w, y, z) as a Vector3d; setting assigns them to W, Y, Z in the same order.</summary>
  public Vector3d Wyz { readonly get => new(W, Y, Z); set { W = value.X; Y = value.Y; Z = value.Z; } }
  /// <summary>The components (w, z, x) as a Vector3d; setting assigns them to W, Z, X in the same order.</summary>
  public Vector3d Wzx { readonly get => new(W, Z, X); set { W = value.X; Z = value.Y; X = value.Z; } }
  /// <summary>The components (w, z, y) as a Vector3d; setting assigns them to W, Z, Y in the same order.</summary>
  public Vector3d Wzy { readonly get => new(W, Z, Y); set { W = value.X; Z = value.Y; Y = value.Z; } }
  /// <summary>The components (x, y, w, z) as a Vector4d; setting assigns them to X, Y, W, Z in the same
  /// order.</summary>
  public Vector4d Xywz { readonly get => new(X, Y, W, Z); set { X = value.X; Y = value.Y; W = value.Z; Z = value.W; } }
  /// <summary>The components (x, z, y, w) as a Vector4d; setting assigns them to X, Z, Y, W in the same
  /// order.</summary>
  public Vector4d Xzyw { readonly get => new(X, Z, Y, W); set { X = value.X; Z = value.Y; Y = value.Z; W = value.W; } }
  /// <summary>The components (x, z, w, y) as a Vector4d; setting assigns them to X, Z, W, Y in the same
  /// order.</summary>
  public Vector4d Xzwy { readonly get => new(X, Z, W, Y); set { X = value.X; Z = value.Y; W = value.Z; Y = value.W; } }
  /// <summary>The components (x, w, y, z) as a Vector4d; setting assigns them to X, W, Y, Z in the same
  /// order.</summary>
  public Vector4d Xwyz { readonly get => new(X, W, Y, Z); set { X = value.X; W = value.Y; Y = value.Z; Z = value.W; } }
  /// <summary>The components (x, w, z, y) as a Vector4d; setting assigns them to X, W, Z, Y in the same
  /// order.</summary>
  public Vector4d Xwzy { readonly get => new(X, W, Z, Y); set { X = value.X; W = value.Y; Z = value.Z; Y = value.W; } }
  /// <summary>The components (y, x, z, w) as a Vector4d; setting assigns them to Y, X, Z, W in the same
  /// order.</summary>
  public Vector4d Yxzw { readonly get => new(Y, X, Z, W); set { Y = value.X; X = value.Y; Z = value.Z; W = value.W; } }
  /// <summary>The components (y, x, w, z) as a Vector4d; setting assigns them to Y, X, W, Z in the same
  /// order.</summary>
  public Vector4d Yxwz { readonly get => new(Y, X, W, Z); set { Y = value.X; X = value.Y; W = value.Z; Z = value.W; } }
  /// <summary>The components (y, z, x, w) as a Vector4d; setting assigns them to Y, Z, X, W in the same
  /// order.</summary>
  public Vector4d Yzxw { readonly get => new(Y, Z, X, W); set { Y = value.X; Z = value.Y; X = value.Z; W = value.W; } }
  /// <summary>The components (y, z, w, x) as a Vector4d; setting assigns them to Y, Z, W, X in the same
  /// order.</summary>
  public Vector4d Yzwx { readonly get => new(Y, Z, W, X); set { Y = value.X; Z = value.Y; W = value.Z; X = value.W; } }
  /// <summary>The components (y, w, x, z) as a Vector4d; setting assigns them to Y, W, X, Z in the same
  /// order.</summary>
  public Vector4d Ywxz { readonly get => new(Y, W, X, Z); set { Y = value.X; W = value.Y; X = value.Z; Z = value.W; } }
  /// <summary>The components (y, w, z, x) as a Vector4d; setting assigns them to Y, W, Z, X in the same
  /// order.</summary>
  public Vector4d Ywzx { readonly get => new(Y, W, Z, X); set { Y = value.X; W = value.Y; Z = value.Z; X = value.W; } }
  /// <summary>The components (z, x, y, w) as a Vector4d; setting assigns them to Z, X, Y, W in the same
  /// order.</summary>
  public Vector4d Zxyw { readonly get => new(Z, X, Y, W); set { Z = value.X; X = value.Y; Y = value.Z; W = value.W; } }
  /// <summary>The components (z, x, w, y) as a Vector4d; setting assigns them to Z, X, W, Y in the same
  /// order.</summary>
  public Vector4d Zxwy { readonly get => new(Z, X, W, Y); set { Z = value.X; X = value.Y; W = value.Z; Y = value.W; } }
  /// <summary>The components (z, y, x, w) as a Vector4d; setting assigns them to Z, Y, X, W in the same
  /// order.</summary>
  public Vector4d Zyxw { readonly get => new(Z, Y, X, W); set { Z = value.X; Y = value.Y; X = value.Z; W = value.W; } }
  /// <summary>The components (z, y, w, x) as a Vector4d; setting assigns them to Z, Y, W, X in the same
  /// order.</summary>
  public Vector4d Zywx { readonly get => new(Z, Y, W, X); set { Z = value.X; Y = value.Y; W = value.Z; X = value.W; } }
  /// <summary>The components (z, w, x, y) as a Vector4d; setting assigns them to Z, W, X, Y in the same
  /// order.</summary>
  public Vector4d Zwxy { readonly get => new(Z, W, X, Y); set { Z = value.X; W = value.Y; X = value.Z; Y = value.W; } }
  /// <summary>The components (z, w, y, x) as a Vector4d; setting assigns them to Z, W, Y, X in the same
  /// order.</summary>
  public Vector4d Zwyx { readonly get => new(Z, W, Y, X); set { Z = value.X; W = value.Y; Y = value.Z; X = value.W; } }
  /// <summary>The components (w, x, y, z) as a Vector4d; setting assigns them to W, X, Y, Z in the same
  /// order.</summary>
  public Vector4d Wxyz { readonly get => new(W, X, Y, Z); set { W = value.X; X = value.Y; Y = value.Z; Z = value.W; } }
  /// <summary>The components (w, x, z, y) as a Vector4d; setting assigns them to W, X, Z, Y in the same
  /// order.</summary>
  public Vector4d Wxzy { readonly get => new(W, X, Z, Y); set { W = value.X; X = value.Y; Z = value.Z; Y = value.W; } }
  /// <summary>The components (w, y, x, z) as a Vector4d; setting assigns them to W, Y, X, Z in the same
  /// order.</summary>
  public Vector4d Wyxz { readonly get => new(W, Y, X, Z); set { W = value.X; Y = value.Y; X = value.Z; Z = value.W; } }
  /// <summary>The components (w, y, z, x) as a Vector4d; setting assigns them to W, Y, Z, X in the same
  /// order.</summary>
  public Vector4d Wyzx { readonly get => new(W, Y, Z, X); set { W = value.X; Y = value.Y; Z = value.Z; X = value.W; } }
  /// <summary>The components (w, z, x, y) as a Vector4d; setting assigns them to W, Z, X, Y in the same
  /// order.</summary>
  public Vector4d Wzxy { readonly get => new(W, Z, X, Y); set { W = value.X; Z = value.Y; X = value.Z; Y = value.W; } }
  /// <summary>The components (w, z, y, x) as a Vector4d; setting assigns them to W, Z, Y, X in the same
  /// order.</summary>
  public Vector4d Wzyx { readonly get => new(W, Z, Y, X); set { W = value.X; Z = value.Y; Y = value.Z; X = value.W; } }

  // Four OpenTK 3 swizzles repeat a component (typos for permutations). Kept as OpenTK has them: the getter
  // reads the letters named, the setter writes the first value to X and the others to the letters after the first.
  /// <summary>Reads (y, y, z, w); setting assigns the value to X, Y, Z, W (OpenTK 3's slip for a permutation, kept as
  /// is).</summary>
  public Vector4d Yyzw { readonly get => new(Y, Y, Z, W); set { X = value.X; Y = value.Y; Z = value.Z; W = value.W; } }
  /// <summary>Reads (y, y, w, z); setting assigns the value to X, Y, W, Z (OpenTK 3's slip for a permutation, kept as
  /// is).</summary>
  public Vector4d Yywz { readonly get => new(Y, Y, W, Z); set { X = value.X; Y = value.Y; W = value.Z; Z = value.W; } }
  /// <summary>Reads (z, w, z, y); setting assigns the value to X, W, Z, Y (OpenTK 3's slip for a permutation, kept as
  /// is).</summary>
  public Vector4d Zwzy { readonly get => new(Z, W, Z, Y); set { X = value.X; W = value.Y; Z = value.Z; Y = value.W; } }
  /// <summary>Reads (w, z, y, w); setting assigns the value to X, Z, Y, W (OpenTK 3's slip for a permutation, kept as
  /// is).</summary>
  public Vector4d Wzyw { readonly get => new(W, Z, Y, W); set { X = value.X; Z = value.Y; Y = value.Z; W = value.W; } }
}
