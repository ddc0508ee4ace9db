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
  /// <summary>The rows; a row vector v is transformed as v · M = v.x·Row0 + v.y·Row1.</summary>
  public Vector2 Row0, Row1;

  /// <summary>The identity matrix.</summary>
  public static readonly Matrix2 Identity = new(Vector2.UnitX, Vector2.UnitY);
  /// <summary>The matrix with every element 0.</summary>
  public static readonly Matrix2 Zero = new(Vector2.Zero, Vector2.Zero);

  /// <summary>The matrix with the given rows.</summary>
  public Matrix2(Vector2 row0, Vector2 row1) { Row0 = row0; Row1 = row1; }
  /// <summary>The matrix from its elements row by row: m<i>rc</i> is row r, column c (from 0).</summary>
  public Matrix2(float m00, float m01, float m10, float m11) { Row0 = new Vector2(m00, m01); Row1 = new Vector2(m10, m11); }

  /// <summary>The element in row 1, column 1 (counted from 1): <c>Row0.X</c>.</summary>
  public float M11 { readonly get => Row0.X; set => Row0.X = value; }
  /// <summary>The element in row 1, column 2 (counted from 1): <c>Row0.Y</c>.</summary>
  public float M12 { readonly get => Row0.Y; set => Row0.Y = value; }
  /// <summary>The element in row 2, column 1 (counted from 1): <c>Row1.X</c>.</summary>
  public float M21 { readonly get => Row1.X; set => Row1.X = value; }
  /// <summary>The element in row 2, column 2 (counted from 1): <c>Row1.Y</c>.</summary>
  public float M22 { readonly get => Row1.Y; set => Row1.Y = value; }
  /// <summary>Column 0: the X of every row; setting writes it back into the rows.</summary>
  public Vector2 Column0 { readonly get => new(Row0.X, Row1.X); set { Row0.X = value.X; Row1.X = value.Y; } }
  /// <summary>Column 1: the Y of every row; setting writes it back into the rows.</summary>
  public Vector2 Column1 { readonly get => new(Row0.Y, Row1.Y); set { Row0.Y = value.X; Row1.Y = value.Y; } }
  /// <summary>The main diagonal (M11, M22, …); setting writes it back, leaving the other elements.</summary>
  public Vector2 Diagonal { readonly get => new(Row0.X, Row1.Y); set { Row0.X = value.X; Row1.Y = value.Y; } }
  /// <summary>The trace: the sum of the diagonal elements.</summary>
  public readonly float Trace => Row0.X + Row1.Y;
  /// <summary>The determinant M11·M22 − M12·M21.</summary>
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

  /// <summary>Replaces the matrix by its inverse; a singular matrix throws
  /// <see cref="System.InvalidOperationException"/>.</summary>
  public void Invert() => this = Invert(this);
  /// <summary>The inverse; unlike the 3×3 and 4×4 matrices' Inverted, a singular matrix throws
  /// <see cref="System.InvalidOperationException"/>.</summary>
  public readonly Matrix2 Inverted() => Invert(this);
  /// <summary>Transposes the matrix in place.</summary>
  public void Transpose() => this = Transpose(this);
  /// <summary>A transposed copy.</summary>
  public readonly Matrix2 Transposed() => Transpose(this);
  /// <summary>Reorders the rows in place, as <see cref="Swizzle(Matrix2, int, int)"/>.</summary>
  public void Swizzle(int rowForRow0, int rowForRow1) => this = Swizzle(this, rowForRow0, rowForRow1);
  /// <summary>A copy with its rows reordered, as <see cref="Swizzle(Matrix2, int, int)"/>.</summary>
  public readonly Matrix2 Swizzled(int rowForRow0, int rowForRow1) => Swizzle(this, rowForRow0, rowForRow1);

  /// <summary>Counter-clockwise by <paramref name="angle"/> radians for row vectors.</summary>
  public static Matrix2 CreateRotation(float angle)
  {
    float cos = MathF.Cos(angle), sin = MathF.Sin(angle);
    return new Matrix2(cos, sin, -sin, cos);
  }

  /// <summary><see cref="CreateRotation(float)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateRotation(float angle, out Matrix2 result) => result = CreateRotation(angle);
  /// <summary>A uniform scale by <paramref name="scale"/>: the diagonal (scale, scale).</summary>
  public static Matrix2 CreateScale(float scale) => new(scale, 0, 0, scale);
  /// <summary><see cref="CreateScale(float)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateScale(float scale, out Matrix2 result) => result = CreateScale(scale);
  /// <summary>A scale by scale.X along x and scale.Y along y.</summary>
  public static Matrix2 CreateScale(Vector2 scale) => new(scale.X, 0, 0, scale.Y);
  /// <summary><see cref="CreateScale(Vector2)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateScale(Vector2 scale, out Matrix2 result) => result = CreateScale(scale);
  /// <summary>A scale by <paramref name="x"/> along x and <paramref name="y"/> along y.</summary>
  public static Matrix2 CreateScale(float x, float y) => new(x, 0, 0, y);
  /// <summary><see cref="CreateScale(float, float)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateScale(float x, float y, out Matrix2 result) => result = CreateScale(x, y);

  /// <summary>The matrix that, multiplied from the left, picks rows <paramref name="rowForRow0"/> and <paramref name="rowForRow1"/>.</summary>
  public static Matrix2 CreateSwizzle(int rowForRow0, int rowForRow1) => Swizzle(Identity, rowForRow0, rowForRow1);
  /// <summary><see cref="CreateSwizzle(int, int)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateSwizzle(int rowForRow0, int rowForRow1, out Matrix2 result) => result = CreateSwizzle(rowForRow0, rowForRow1);

  /// <summary>A matrix whose rows are rows <paramref name="rowForRow0"/> and <paramref name="rowForRow1"/> of <paramref name="mat"/>.</summary>
  public static Matrix2 Swizzle(Matrix2 mat, int rowForRow0, int rowForRow1) => new(Row(mat, rowForRow0), Row(mat, rowForRow1));
  /// <summary><see cref="Swizzle(Matrix2, int, int)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Swizzle(in Matrix2 mat, int rowForRow0, int rowForRow1, out Matrix2 result) => result = Swizzle(mat, rowForRow0, rowForRow1);

  static Vector2 Row(in Matrix2 m, int i) => i switch
  {
    0 => m.Row0, 1 => m.Row1,
    _ => throw new ArgumentOutOfRangeException(nameof(i), $"Matrix2 row {i} is outside 0..1."),
  };

  /// <summary>Every element multiplied by the scalar.</summary>
  public static Matrix2 Mult(Matrix2 left, float right) => new(left.Row0 * right, left.Row1 * right);
  /// <summary><see cref="Mult(Matrix2, float)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Mult(in Matrix2 left, float right, out Matrix2 result) => result = Mult(left, right);
  /// <summary>The matrix product, as the <c>*</c> operator: with row vectors, v · (A · B) applies A first, then
  /// B.</summary>
  public static Matrix2 Mult(Matrix2 left, Matrix2 right) => new(
    left.Row0.X * right.Row0.X + left.Row0.Y * right.Row1.X, left.Row0.X * right.Row0.Y + left.Row0.Y * right.Row1.Y,
    left.Row1.X * right.Row0.X + left.Row1.Y * right.Row1.X, left.Row1.X * right.Row0.Y + left.Row1.Y * right.Row1.Y);
  /// <summary><see cref="Mult(Matrix2, Matrix2)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Mult(in Matrix2 left, in Matrix2 right, out Matrix2 result) => result = Mult(left, right);
  /// <summary>The sum, element by element.</summary>
  public static Matrix2 Add(Matrix2 left, Matrix2 right) => new(left.Row0 + right.Row0, left.Row1 + right.Row1);
  /// <summary><see cref="Add(Matrix2, Matrix2)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Add(in Matrix2 left, in Matrix2 right, out Matrix2 result) => result = Add(left, right);
  /// <summary>The difference, element by element.</summary>
  public static Matrix2 Subtract(Matrix2 left, Matrix2 right) => new(left.Row0 - right.Row0, left.Row1 - right.Row1);
  /// <summary><see cref="Subtract(Matrix2, Matrix2)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Subtract(in Matrix2 left, in Matrix2 right, out Matrix2 result) => result = Subtract(left, right);

  /// <exception cref="InvalidOperationException">The matrix is singular.</exception>
  public static Matrix2 Invert(Matrix2 mat)
  {
    float det = mat.Determinant;
    if (det == 0) throw new InvalidOperationException("Matrix2 is singular and cannot be inverted.");
    float s = 1f / det;
    return new Matrix2(mat.Row1.Y * s, -mat.Row0.Y * s, -mat.Row1.X * s, mat.Row0.X * s);
  }

  /// <summary><see cref="Invert(Matrix2)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Invert(in Matrix2 mat, out Matrix2 result) => result = Invert(mat);
  /// <summary>The transpose: rows and columns swapped.</summary>
  public static Matrix2 Transpose(Matrix2 mat) => new(mat.Column0, mat.Column1);
  /// <summary><see cref="Transpose(Matrix2)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Transpose(in Matrix2 mat, out Matrix2 result) => result = Transpose(mat);

  /// <summary>Every element multiplied by the scalar.</summary>
  public static Matrix2 operator *(float left, Matrix2 right) => Mult(right, left);
  /// <summary>Every element multiplied by the scalar.</summary>
  public static Matrix2 operator *(Matrix2 left, float right) => Mult(left, right);
  /// <summary>The matrix product A · B (each row of A times B); with row vectors, v · (A · B) applies A first, then
  /// B.</summary>
  public static Matrix2 operator *(Matrix2 left, Matrix2 right) => Mult(left, right);
  /// <summary>The sum, element by element.</summary>
  public static Matrix2 operator +(Matrix2 left, Matrix2 right) => Add(left, right);
  /// <summary>The difference, element by element.</summary>
  public static Matrix2 operator -(Matrix2 left, Matrix2 right) => Subtract(left, right);
  /// <summary>Whether the two are equal, as <see cref="Equals(Matrix2)"/> compares them.</summary>
  public static bool operator ==(Matrix2 left, Matrix2 right) => left.Equals(right);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Matrix2)"/>.</summary>
  public static bool operator !=(Matrix2 left, Matrix2 right) => !left.Equals(right);

  /// <summary>Whether every row equals the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Matrix2 other) => Row0 == other.Row0 && Row1 == other.Row1;
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Matrix2 m && Equals(m);
  /// <inheritdoc/>
  public override readonly int GetHashCode() => HashCode.Combine(Row0, Row1);
  /// <inheritdoc/>
  public override readonly string ToString() => ToString(null, null);
  /// <summary>As <see cref="ToString(string, IFormatProvider)"/> with the current culture.</summary>
  public readonly string ToString(string? format) => ToString(format, null);
  /// <summary>As <see cref="ToString(string, IFormatProvider)"/> with no format.</summary>
  public readonly string ToString(IFormatProvider? formatProvider) => ToString(null, formatProvider);
  /// <summary>The two rows on two lines.</summary>
  public readonly string ToString(string? format, IFormatProvider? formatProvider) =>
    string.Format(formatProvider ?? CultureInfo.CurrentCulture, "{0}\n{1}", Row0, Row1);
}
