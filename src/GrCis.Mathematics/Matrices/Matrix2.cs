using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>
/// OpenTK 4's single-precision 2×2 matrix (row vectors: <c>v' = v · M</c>), computed in float in OpenTK's order.
/// The rectangular matrices (<c>Matrix2x3</c> …) are not ported, so neither are the products with them.
/// </summary>
[Serializable]
[OpenTk3RefForms]
public partial struct Matrix2 : IEquatable<Matrix2>, IFormattable
{
  public Vector2 Row0, Row1;

  public static readonly Matrix2 Identity = new(Vector2.UnitX, Vector2.UnitY);
  public static readonly Matrix2 Zero = new(Vector2.Zero, Vector2.Zero);

  public Matrix2(Vector2 row0, Vector2 row1) { Row0 = row0; Row1 = row1; }
  public Matrix2(float m00, float m01, float m10, float m11) { Row0 = new Vector2(m00, m01); Row1 = new Vector2(m10, m11); }

  public float M11 { readonly get => Row0.X; set => Row0.X = value; }
  public float M12 { readonly get => Row0.Y; set => Row0.Y = value; }
  public float M21 { readonly get => Row1.X; set => Row1.X = value; }
  public float M22 { readonly get => Row1.Y; set => Row1.Y = value; }
  public Vector2 Column0 { readonly get => new(Row0.X, Row1.X); set { Row0.X = value.X; Row1.X = value.Y; } }
  public Vector2 Column1 { readonly get => new(Row0.Y, Row1.Y); set { Row0.Y = value.X; Row1.Y = value.Y; } }
  public Vector2 Diagonal { readonly get => new(Row0.X, Row1.Y); set { Row0.X = value.X; Row1.Y = value.Y; } }
  public readonly float Trace => Row0.X + Row1.Y;
  public readonly float Determinant => Row0.X * Row1.Y - Row0.Y * Row1.X;

  /// <summary>The element in row <paramref name="rowIndex"/>, column <paramref name="columnIndex"/> (both 0..1).</summary>
  public float this[int rowIndex, int columnIndex]
  {
    readonly get => rowIndex switch
    {
      0 => Row0[columnIndex], 1 => Row1[columnIndex],
      _ => throw new IndexOutOfRangeException($"Matrix2 row {rowIndex} is outside 0..1."),
    };
    set
    {
      switch (rowIndex)
      {
        case 0: Row0[columnIndex] = value; break;
        case 1: Row1[columnIndex] = value; break;
        default: throw new IndexOutOfRangeException($"Matrix2 row {rowIndex} is outside 0..1.");
      }
    }
  }

  public void Invert() => this = Invert(this);
  public readonly Matrix2 Inverted() => Invert(this);
  public void Transpose() => this = Transpose(this);
  public readonly Matrix2 Transposed() => Transpose(this);
  public void Swizzle(int rowForRow0, int rowForRow1) => this = Swizzle(this, rowForRow0, rowForRow1);
  public readonly Matrix2 Swizzled(int rowForRow0, int rowForRow1) => Swizzle(this, rowForRow0, rowForRow1);

  /// <summary>Counter-clockwise by <paramref name="angle"/> radians for row vectors.</summary>
  public static Matrix2 CreateRotation(float angle)
  {
    float cos = MathF.Cos(angle), sin = MathF.Sin(angle);
    return new Matrix2(cos, sin, -sin, cos);
  }

  public static void CreateRotation(float angle, out Matrix2 result) => result = CreateRotation(angle);
  public static Matrix2 CreateScale(float scale) => new(scale, 0, 0, scale);
  public static void CreateScale(float scale, out Matrix2 result) => result = CreateScale(scale);
  public static Matrix2 CreateScale(Vector2 scale) => new(scale.X, 0, 0, scale.Y);
  public static void CreateScale(Vector2 scale, out Matrix2 result) => result = CreateScale(scale);
  public static Matrix2 CreateScale(float x, float y) => new(x, 0, 0, y);
  public static void CreateScale(float x, float y, out Matrix2 result) => result = CreateScale(x, y);

  /// <summary>The matrix that, multiplied from the left, picks rows <paramref name="rowForRow0"/> and <paramref name="rowForRow1"/>.</summary>
  public static Matrix2 CreateSwizzle(int rowForRow0, int rowForRow1) => Swizzle(Identity, rowForRow0, rowForRow1);
  public static void CreateSwizzle(int rowForRow0, int rowForRow1, out Matrix2 result) => result = CreateSwizzle(rowForRow0, rowForRow1);

  /// <summary>A matrix whose rows are rows <paramref name="rowForRow0"/> and <paramref name="rowForRow1"/> of <paramref name="mat"/>.</summary>
  public static Matrix2 Swizzle(Matrix2 mat, int rowForRow0, int rowForRow1) => new(Row(mat, rowForRow0), Row(mat, rowForRow1));
  public static void Swizzle(in Matrix2 mat, int rowForRow0, int rowForRow1, out Matrix2 result) => result = Swizzle(mat, rowForRow0, rowForRow1);

  static Vector2 Row(in Matrix2 m, int i) => i switch
  {
    0 => m.Row0, 1 => m.Row1,
    _ => throw new ArgumentOutOfRangeException(nameof(i), $"Matrix2 row {i} is outside 0..1."),
  };

  public static Matrix2 Mult(Matrix2 left, float right) => new(left.Row0 * right, left.Row1 * right);
  public static void Mult(in Matrix2 left, float right, out Matrix2 result) => result = Mult(left, right);
  public static Matrix2 Mult(Matrix2 left, Matrix2 right) => new(
    left.Row0.X * right.Row0.X + left.Row0.Y * right.Row1.X, left.Row0.X * right.Row0.Y + left.Row0.Y * right.Row1.Y,
    left.Row1.X * right.Row0.X + left.Row1.Y * right.Row1.X, left.Row1.X * right.Row0.Y + left.Row1.Y * right.Row1.Y);
  public static void Mult(in Matrix2 left, in Matrix2 right, out Matrix2 result) => result = Mult(left, right);
  public static Matrix2 Add(Matrix2 left, Matrix2 right) => new(left.Row0 + right.Row0, left.Row1 + right.Row1);
  public static void Add(in Matrix2 left, in Matrix2 right, out Matrix2 result) => result = Add(left, right);
  public static Matrix2 Subtract(Matrix2 left, Matrix2 right) => new(left.Row0 - right.Row0, left.Row1 - right.Row1);
  public static void Subtract(in Matrix2 left, in Matrix2 right, out Matrix2 result) => result = Subtract(left, right);

  /// <exception cref="InvalidOperationException">The matrix is singular.</exception>
  public static Matrix2 Invert(Matrix2 mat)
  {
    float det = mat.Determinant;
    if (det == 0) throw new InvalidOperationException("Matrix2 is singular and cannot be inverted.");
    float s = 1f / det;
    return new Matrix2(mat.Row1.Y * s, -mat.Row0.Y * s, -mat.Row1.X * s, mat.Row0.X * s);
  }

  public static void Invert(in Matrix2 mat, out Matrix2 result) => result = Invert(mat);
  public static Matrix2 Transpose(Matrix2 mat) => new(mat.Column0, mat.Column1);
  public static void Transpose(in Matrix2 mat, out Matrix2 result) => result = Transpose(mat);

  public static Matrix2 operator *(float left, Matrix2 right) => Mult(right, left);
  public static Matrix2 operator *(Matrix2 left, float right) => Mult(left, right);
  public static Matrix2 operator *(Matrix2 left, Matrix2 right) => Mult(left, right);
  public static Matrix2 operator +(Matrix2 left, Matrix2 right) => Add(left, right);
  public static Matrix2 operator -(Matrix2 left, Matrix2 right) => Subtract(left, right);
  public static bool operator ==(Matrix2 left, Matrix2 right) => left.Equals(right);
  public static bool operator !=(Matrix2 left, Matrix2 right) => !left.Equals(right);

  public readonly bool Equals(Matrix2 other) => Row0 == other.Row0 && Row1 == other.Row1;
  public override readonly bool Equals(object? obj) => obj is Matrix2 m && Equals(m);
  public override readonly int GetHashCode() => HashCode.Combine(Row0, Row1);
  public override readonly string ToString() => ToString(null, null);
  public readonly string ToString(string? format) => ToString(format, null);
  public readonly string ToString(IFormatProvider? formatProvider) => ToString(null, formatProvider);
  /// <summary>The two rows on two lines.</summary>
  public readonly string ToString(string? format, IFormatProvider? formatProvider) =>
    string.Format(formatProvider ?? CultureInfo.CurrentCulture, "{0}\n{1}", Row0, Row1);
}
