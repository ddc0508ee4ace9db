using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>
/// OpenTK's single-precision 3×3 matrix (row vectors: <c>v' = v · M</c>): a rotation or scale without
/// translation. Products and transforms are computed in float in OpenTK's order; rotations about an axis,
/// the inverse and the rotation's quaternion are <see cref="Matrix3d"/>'s, rounded back to float.
/// </summary>
[OpenTk3RefForms]
public partial struct Matrix3 : IEquatable<Matrix3>
{
  /// <summary>The rows; a row vector v is transformed as v · M = v.x·Row0 + v.y·Row1 + v.z·Row2.</summary>
  public Vector3 Row0, Row1, Row2;

  /// <summary>The identity matrix.</summary>
  public static readonly Matrix3 Identity = new(Vector3.UnitX, Vector3.UnitY, Vector3.UnitZ);
  /// <summary>The matrix with every element 0.</summary>
  public static readonly Matrix3 Zero = new(Vector3.Zero, Vector3.Zero, Vector3.Zero);

  /// <summary>The matrix with the given rows.</summary>
  public Matrix3(Vector3 row0, Vector3 row1, Vector3 row2) => (Row0, Row1, Row2) = (row0, row1, row2);

  /// <summary>The matrix from its elements row by row: m<i>rc</i> is row r, column c (from 0).</summary>
  public Matrix3(float m00, float m01, float m02, float m10, float m11, float m12, float m20, float m21, float m22)
    : this(new Vector3(m00, m01, m02), new Vector3(m10, m11, m12), new Vector3(m20, m21, m22))
  {
  }

  /// <summary>The upper-left 3×3 part.</summary>
  public Matrix3(Matrix4 m) : this(m.Row0.Xyz, m.Row1.Xyz, m.Row2.Xyz)
  {
  }

  /// <summary>The element in row 1, column 1 (counted from 1): <c>Row0.X</c>.</summary>
  public float M11 { readonly get => Row0.X; set => Row0.X = value; }
  /// <summary>The element in row 1, column 2 (counted from 1): <c>Row0.Y</c>.</summary>
  public float M12 { readonly get => Row0.Y; set => Row0.Y = value; }
  /// <summary>The element in row 1, column 3 (counted from 1): <c>Row0.Z</c>.</summary>
  public float M13 { readonly get => Row0.Z; set => Row0.Z = value; }
  /// <summary>The element in row 2, column 1 (counted from 1): <c>Row1.X</c>.</summary>
  public float M21 { readonly get => Row1.X; set => Row1.X = value; }
  /// <summary>The element in row 2, column 2 (counted from 1): <c>Row1.Y</c>.</summary>
  public float M22 { readonly get => Row1.Y; set => Row1.Y = value; }
  /// <summary>The element in row 2, column 3 (counted from 1): <c>Row1.Z</c>.</summary>
  public float M23 { readonly get => Row1.Z; set => Row1.Z = value; }
  /// <summary>The element in row 3, column 1 (counted from 1): <c>Row2.X</c>.</summary>
  public float M31 { readonly get => Row2.X; set => Row2.X = value; }
  /// <summary>The element in row 3, column 2 (counted from 1): <c>Row2.Y</c>.</summary>
  public float M32 { readonly get => Row2.Y; set => Row2.Y = value; }
  /// <summary>The element in row 3, column 3 (counted from 1): <c>Row2.Z</c>.</summary>
  public float M33 { readonly get => Row2.Z; set => Row2.Z = value; }

  /// <summary>The six-term expansion in float, as OpenTK 3 evaluates it, so <see cref="Inverted"/> finds the same matrices singular.</summary>
  public readonly float Determinant =>
    Row0.X * Row1.Y * Row2.Z + Row0.Y * Row1.Z * Row2.X + Row0.Z * Row1.X * Row2.Y
    - Row0.Z * Row1.Y * Row2.X - Row0.X * Row1.Z * Row2.Y - Row0.Y * Row1.X * Row2.Z;

  // This port's conversions, as between Matrix4 and Matrix4d: widening is exact, narrowing rounds.
  /// <summary>The matrix widened to double (exact).</summary>
  public static implicit operator Matrix3d(Matrix3 m) => new(m.Row0, m.Row1, m.Row2);
  /// <summary>Each element rounded to float.</summary>
  public static explicit operator Matrix3(Matrix3d m) => new((Vector3)m.Row0, (Vector3)m.Row1, (Vector3)m.Row2);

  /// <summary>A rotation by <paramref name="angle"/> radians about the X axis, right-handed (y turns towards z);
  /// computed in double and rounded.</summary>
  public static Matrix3 CreateRotationX(float angle) => (Matrix3)Matrix3d.CreateRotationX(angle);
  /// <summary>A rotation by <paramref name="angle"/> radians about the Y axis, right-handed (z turns towards x);
  /// computed in double and rounded.</summary>
  public static Matrix3 CreateRotationY(float angle) => (Matrix3)Matrix3d.CreateRotationY(angle);
  /// <summary>A rotation by <paramref name="angle"/> radians about the Z axis, right-handed (x turns towards y);
  /// computed in double and rounded.</summary>
  public static Matrix3 CreateRotationZ(float angle) => (Matrix3)Matrix3d.CreateRotationZ(angle);
  /// <summary>A right-handed rotation by <paramref name="angle"/> radians about <paramref name="axis"/> (normalized
  /// first; a zero axis gives NaN), as <see cref="Matrix4d.CreateFromAxisAngle(Vector3d, double)"/>.</summary>
  public static Matrix3 CreateFromAxisAngle(Vector3 axis, float angle) => (Matrix3)Matrix3d.CreateFromAxisAngle(axis, angle);
  /// <summary>A uniform scale by <paramref name="s"/>: the diagonal (s, s, s).</summary>
  public static Matrix3 CreateScale(float s) => CreateScale(s, s, s);
  /// <summary>A scale by x, y and z along the axes: the diagonal (x, y, z).</summary>
  public static Matrix3 CreateScale(float x, float y, float z) => new(x, 0, 0, 0, y, 0, 0, 0, z);
  /// <summary>A scale by the components of <paramref name="s"/> along the axes.</summary>
  public static Matrix3 CreateScale(Vector3 s) => CreateScale(s.X, s.Y, s.Z);

  /// <summary>The matrix product, as the <c>*</c> operator: with row vectors, v · (A · B) applies A first, then
  /// B.</summary>
  public static Matrix3 Mult(Matrix3 a, Matrix3 b) => a * b;
  /// <summary>Each row of <paramref name="a"/> times <paramref name="b"/>: <c>v · (A · B) = (v · A) · B</c>.</summary>
  public static Matrix3 operator *(Matrix3 a, Matrix3 b) => new(a.Row0 * b, a.Row1 * b, a.Row2 * b);
  /// <summary>Whether the two are equal, as <see cref="Equals(Matrix3)"/> compares them.</summary>
  public static bool operator ==(Matrix3 a, Matrix3 b) => a.Equals(b);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Matrix3)"/>.</summary>
  public static bool operator !=(Matrix3 a, Matrix3 b) => !a.Equals(b);

  /// <summary>The transpose: rows and columns swapped.</summary>
  public static Matrix3 Transpose(Matrix3 m) => new(m.Column0, m.Column1, m.Column2);
  /// <summary>Transposes the matrix in place.</summary>
  public void Transpose() => this = Transpose(this);
  /// <summary>A transposed copy.</summary>
  public readonly Matrix3 Transposed() => Transpose(this);

  /// <exception cref="InvalidOperationException">The matrix is singular.</exception>
  public static Matrix3 Invert(Matrix3 m) => (Matrix3)Matrix3d.Invert(m);
  /// <summary>Replaces the matrix by its inverse; a singular matrix throws
  /// <see cref="System.InvalidOperationException"/>.</summary>
  public void Invert() => this = Invert(this);

  /// <summary>The inverse, or (as in OpenTK 3) the matrix unchanged when its determinant is 0.</summary>
  public readonly Matrix3 Inverted() => Determinant == 0 ? this : Invert(this);

  /// <summary>Whether every row equals the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Matrix3 other) => Row0 == other.Row0 && Row1 == other.Row1 && Row2 == other.Row2;
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Matrix3 m && Equals(m);
  /// <inheritdoc/>
  public override readonly int GetHashCode() => HashCode.Combine(Row0, Row1, Row2);
  /// <inheritdoc/>
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "{0}\n{1}\n{2}", Row0, Row1, Row2);
}
