using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>
/// OpenTK's double-precision 3×3 matrix (row vectors: <c>v' = v · M</c>): a rotation or scale without
/// translation. Arithmetic goes through <see cref="Matrix4d"/>.
/// </summary>
[OpenTk3RefForms]
public partial struct Matrix3d : IEquatable<Matrix3d>
{
  /// <summary>The rows; a row vector v is transformed as v · M = v.x·Row0 + v.y·Row1 + v.z·Row2.</summary>
  public Vector3d Row0, Row1, Row2;

  /// <summary>The identity matrix.</summary>
  public static readonly Matrix3d Identity = new(Vector3d.UnitX, Vector3d.UnitY, Vector3d.UnitZ);
  /// <summary>The matrix with every element 0.</summary>
  public static readonly Matrix3d Zero = new(Vector3d.Zero, Vector3d.Zero, Vector3d.Zero);

  /// <summary>The matrix with the given rows.</summary>
  public Matrix3d(Vector3d row0, Vector3d row1, Vector3d row2) => (Row0, Row1, Row2) = (row0, row1, row2);

  /// <summary>The matrix from its elements row by row: m<i>rc</i> is row r, column c (from 0).</summary>
  public Matrix3d(double m00, double m01, double m02, double m10, double m11, double m12, double m20, double m21, double m22)
    : this(new Vector3d(m00, m01, m02), new Vector3d(m10, m11, m12), new Vector3d(m20, m21, m22))
  {
  }

  /// <summary>The upper-left 3×3 part.</summary>
  public Matrix3d(Matrix4d m) : this(m.Row0.Xyz, m.Row1.Xyz, m.Row2.Xyz)
  {
  }

  /// <summary>The element in row 1, column 1 (counted from 1): <c>Row0.X</c>.</summary>
  public double M11 { readonly get => Row0.X; set => Row0.X = value; }
  /// <summary>The element in row 1, column 2 (counted from 1): <c>Row0.Y</c>.</summary>
  public double M12 { readonly get => Row0.Y; set => Row0.Y = value; }
  /// <summary>The element in row 1, column 3 (counted from 1): <c>Row0.Z</c>.</summary>
  public double M13 { readonly get => Row0.Z; set => Row0.Z = value; }
  /// <summary>The element in row 2, column 1 (counted from 1): <c>Row1.X</c>.</summary>
  public double M21 { readonly get => Row1.X; set => Row1.X = value; }
  /// <summary>The element in row 2, column 2 (counted from 1): <c>Row1.Y</c>.</summary>
  public double M22 { readonly get => Row1.Y; set => Row1.Y = value; }
  /// <summary>The element in row 2, column 3 (counted from 1): <c>Row1.Z</c>.</summary>
  public double M23 { readonly get => Row1.Z; set => Row1.Z = value; }
  /// <summary>The element in row 3, column 1 (counted from 1): <c>Row2.X</c>.</summary>
  public double M31 { readonly get => Row2.X; set => Row2.X = value; }
  /// <summary>The element in row 3, column 2 (counted from 1): <c>Row2.Y</c>.</summary>
  public double M32 { readonly get => Row2.Y; set => Row2.Y = value; }
  /// <summary>The element in row 3, column 3 (counted from 1): <c>Row2.Z</c>.</summary>
  public double M33 { readonly get => Row2.Z; set => Row2.Z = value; }

  /// <summary>The six-term expansion OpenTK 3 evaluates, so <see cref="Inverted"/> finds the same matrices singular.</summary>
  public readonly double Determinant =>
    Row0.X * Row1.Y * Row2.Z + Row0.Y * Row1.Z * Row2.X + Row0.Z * Row1.X * Row2.Y
    - Row0.Z * Row1.Y * Row2.X - Row0.X * Row1.Z * Row2.Y - Row0.Y * Row1.X * Row2.Z;

  readonly Matrix4d To4() => new(new Vector4d(Row0, 0), new Vector4d(Row1, 0), new Vector4d(Row2, 0), Vector4d.UnitW);

  /// <summary>A rotation by <paramref name="angle"/> radians about the X axis, right-handed (y turns towards z): the
  /// upper 3×3 of <see cref="Matrix4d.CreateRotationX(double)"/>.</summary>
  public static Matrix3d CreateRotationX(double angle) => new(Matrix4d.CreateRotationX(angle));
  /// <summary>A rotation by <paramref name="angle"/> radians about the Y axis, right-handed (z turns towards x): the
  /// upper 3×3 of <see cref="Matrix4d.CreateRotationY(double)"/>.</summary>
  public static Matrix3d CreateRotationY(double angle) => new(Matrix4d.CreateRotationY(angle));
  /// <summary>A rotation by <paramref name="angle"/> radians about the Z axis, right-handed (x turns towards y): the
  /// upper 3×3 of <see cref="Matrix4d.CreateRotationZ(double)"/>.</summary>
  public static Matrix3d CreateRotationZ(double angle) => new(Matrix4d.CreateRotationZ(angle));
  /// <summary>A right-handed rotation by <paramref name="angle"/> radians about <paramref name="axis"/> (normalized
  /// first; a zero axis gives NaN), as <see cref="Matrix4d.CreateFromAxisAngle(Vector3d, double)"/>.</summary>
  public static Matrix3d CreateFromAxisAngle(Vector3d axis, double angle) => new(Matrix4d.CreateFromAxisAngle(axis, angle));
  /// <summary>A uniform scale by <paramref name="s"/>: the diagonal (s, s, s).</summary>
  public static Matrix3d CreateScale(double s) => CreateScale(s, s, s);
  /// <summary>A scale by x, y and z along the axes: the diagonal (x, y, z).</summary>
  public static Matrix3d CreateScale(double x, double y, double z) => new(x, 0, 0, 0, y, 0, 0, 0, z);
  /// <summary>A scale by the components of <paramref name="s"/> along the axes.</summary>
  public static Matrix3d CreateScale(Vector3d s) => CreateScale(s.X, s.Y, s.Z);

  /// <summary>The matrix product, as the <c>*</c> operator: with row vectors, v · (A · B) applies A first, then
  /// B.</summary>
  public static Matrix3d Mult(Matrix3d a, Matrix3d b) => a * b;
  /// <summary>The matrix product A · B (each row of A times B); with row vectors, v · (A · B) applies A first, then
  /// B.</summary>
  public static Matrix3d operator *(Matrix3d a, Matrix3d b) => new(a.To4() * b.To4());
  /// <summary>The row vector times the matrix, v · M = v.x·Row0 + v.y·Row1 + v.z·Row2.</summary>
  public static Vector3d operator *(Vector3d v, Matrix3d m) => v.X * m.Row0 + v.Y * m.Row1 + v.Z * m.Row2;
  /// <summary>Whether the two are equal, as <see cref="Equals(Matrix3d)"/> compares them.</summary>
  public static bool operator ==(Matrix3d a, Matrix3d b) => a.Equals(b);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Matrix3d)"/>.</summary>
  public static bool operator !=(Matrix3d a, Matrix3d b) => !a.Equals(b);

  /// <summary>The transpose: rows and columns swapped.</summary>
  public static Matrix3d Transpose(Matrix3d m) => new(Matrix4d.Transpose(m.To4()));
  /// <summary>Transposes the matrix in place.</summary>
  public void Transpose() => this = Transpose(this);
  /// <summary>A transposed copy.</summary>
  public readonly Matrix3d Transposed() => Transpose(this);
  /// <exception cref="InvalidOperationException">The matrix is singular.</exception>
  public static Matrix3d Invert(Matrix3d m) => new(Matrix4d.Invert(m.To4()));
  /// <summary>Replaces the matrix by its inverse; a singular matrix throws
  /// <see cref="System.InvalidOperationException"/>.</summary>
  public void Invert() => this = Invert(this);
  /// <summary>The inverse, or (as in OpenTK 3) the matrix unchanged when its determinant is 0.</summary>
  public readonly Matrix3d Inverted() => Determinant == 0 ? this : Invert(this);

  /// <summary>Whether every row equals the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Matrix3d other) => Row0 == other.Row0 && Row1 == other.Row1 && Row2 == other.Row2;
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Matrix3d m && Equals(m);
  /// <inheritdoc/>
  public override readonly int GetHashCode() => HashCode.Combine(Row0, Row1, Row2);
  /// <inheritdoc/>
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "{0}\n{1}\n{2}", Row0, Row1, Row2);
}
