using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>
/// OpenTK's single-precision 4×4 matrix (row vectors: <c>v' = v · M</c>, translation in the last row),
/// for GrCis code written with floats (mesh readers, <c>Matrix4.Identity</c> arguments). Products, inverses,
/// determinants and vector transforms are computed in float in OpenTK 3's order of operations, so they give
/// OpenTK's results to the bit; the creators (rotations, projections) go through <see cref="Matrix4d"/> and round.
/// </summary>
[OpenTk3RefForms]
public partial struct Matrix4 : IEquatable<Matrix4>
{
  /// <summary>The rows; a point v is transformed as (v, 1) · M, so Row3 holds the translation.</summary>
  public Vector4 Row0, Row1, Row2, Row3;

  /// <summary>The identity matrix.</summary>
  public static readonly Matrix4 Identity = new(new Vector4(1, 0, 0, 0), new Vector4(0, 1, 0, 0), new Vector4(0, 0, 1, 0), new Vector4(0, 0, 0, 1));
  /// <summary>The matrix with every element 0.</summary>
  public static readonly Matrix4 Zero = new(Vector4.Zero, Vector4.Zero, Vector4.Zero, Vector4.Zero);

  /// <summary>The matrix with the given rows.</summary>
  public Matrix4(Vector4 row0, Vector4 row1, Vector4 row2, Vector4 row3) => (Row0, Row1, Row2, Row3) = (row0, row1, row2, row3);

  /// <summary>The matrix from its elements row by row: m<i>rc</i> is row r, column c (from 0).</summary>
  public Matrix4(float m00, float m01, float m02, float m03, float m10, float m11, float m12, float m13,
                 float m20, float m21, float m22, float m23, float m30, float m31, float m32, float m33)
    : this(new Vector4(m00, m01, m02, m03), new Vector4(m10, m11, m12, m13), new Vector4(m20, m21, m22, m23), new Vector4(m30, m31, m32, m33))
  {
  }

  /// <summary>A 4×4 matrix with <paramref name="topLeft"/> as its rotation/scale part and no translation.</summary>
  public Matrix4(Matrix3 topLeft)
    : this(new Vector4(topLeft.Row0, 0), new Vector4(topLeft.Row1, 0), new Vector4(topLeft.Row2, 0), Vector4.UnitW)
  {
  }

  /// <summary>The element in row 1, column 1 (counted from 1): <c>Row0.X</c>.</summary>
  public float M11 { readonly get => Row0.X; set => Row0.X = value; }
  /// <summary>The element in row 1, column 2 (counted from 1): <c>Row0.Y</c>.</summary>
  public float M12 { readonly get => Row0.Y; set => Row0.Y = value; }
  /// <summary>The element in row 1, column 3 (counted from 1): <c>Row0.Z</c>.</summary>
  public float M13 { readonly get => Row0.Z; set => Row0.Z = value; }
  /// <summary>The element in row 1, column 4 (counted from 1): <c>Row0.W</c>.</summary>
  public float M14 { readonly get => Row0.W; set => Row0.W = value; }
  /// <summary>The element in row 2, column 1 (counted from 1): <c>Row1.X</c>.</summary>
  public float M21 { readonly get => Row1.X; set => Row1.X = value; }
  /// <summary>The element in row 2, column 2 (counted from 1): <c>Row1.Y</c>.</summary>
  public float M22 { readonly get => Row1.Y; set => Row1.Y = value; }
  /// <summary>The element in row 2, column 3 (counted from 1): <c>Row1.Z</c>.</summary>
  public float M23 { readonly get => Row1.Z; set => Row1.Z = value; }
  /// <summary>The element in row 2, column 4 (counted from 1): <c>Row1.W</c>.</summary>
  public float M24 { readonly get => Row1.W; set => Row1.W = value; }
  /// <summary>The element in row 3, column 1 (counted from 1): <c>Row2.X</c>.</summary>
  public float M31 { readonly get => Row2.X; set => Row2.X = value; }
  /// <summary>The element in row 3, column 2 (counted from 1): <c>Row2.Y</c>.</summary>
  public float M32 { readonly get => Row2.Y; set => Row2.Y = value; }
  /// <summary>The element in row 3, column 3 (counted from 1): <c>Row2.Z</c>.</summary>
  public float M33 { readonly get => Row2.Z; set => Row2.Z = value; }
  /// <summary>The element in row 3, column 4 (counted from 1): <c>Row2.W</c>.</summary>
  public float M34 { readonly get => Row2.W; set => Row2.W = value; }
  /// <summary>The element in row 4, column 1 (counted from 1): <c>Row3.X</c>.</summary>
  public float M41 { readonly get => Row3.X; set => Row3.X = value; }
  /// <summary>The element in row 4, column 2 (counted from 1): <c>Row3.Y</c>.</summary>
  public float M42 { readonly get => Row3.Y; set => Row3.Y = value; }
  /// <summary>The element in row 4, column 3 (counted from 1): <c>Row3.Z</c>.</summary>
  public float M43 { readonly get => Row3.Z; set => Row3.Z = value; }
  /// <summary>The element in row 4, column 4 (counted from 1): <c>Row3.W</c>.</summary>
  public float M44 { readonly get => Row3.W; set => Row3.W = value; }

  /// <summary>Each element rounded to float.</summary>
  public static explicit operator Matrix4(Matrix4d m) => new((Vector4)m.Row0, (Vector4)m.Row1, (Vector4)m.Row2, (Vector4)m.Row3);

  /// <summary>The matrix widened to double (exact).</summary>
  public static implicit operator Matrix4d(Matrix4 m) => new(m.Row0, m.Row1, m.Row2, m.Row3);

  /// <summary>A translation by (x, y, z): the identity with Row3 = (x, y, z, 1), for row vectors <c>(v, 1) ·
  /// M</c>.</summary>
  public static Matrix4 CreateTranslation(float x, float y, float z) => (Matrix4)Matrix4d.CreateTranslation(x, y, z);
  /// <summary>A translation by <paramref name="v"/>: the identity with Row3 = (v, 1).</summary>
  public static Matrix4 CreateTranslation(Vector3 v) => CreateTranslation(v.X, v.Y, v.Z);
  /// <summary>A uniform scale by <paramref name="s"/>: the diagonal (s, s, s, 1).</summary>
  public static Matrix4 CreateScale(float s) => (Matrix4)Matrix4d.CreateScale(s);
  /// <summary>A scale by x, y and z along the axes: the diagonal (x, y, z, 1).</summary>
  public static Matrix4 CreateScale(float x, float y, float z) => (Matrix4)Matrix4d.CreateScale(x, y, z);
  /// <summary>A scale by the components of <paramref name="s"/> along the axes: the diagonal (s.X, s.Y, s.Z,
  /// 1).</summary>
  public static Matrix4 CreateScale(Vector3 s) => CreateScale(s.X, s.Y, s.Z);
  /// <summary>A rotation by <paramref name="angle"/> radians about the X axis, right-handed (y turns towards z);
  /// <see cref="Matrix4d.CreateRotationX(double)"/> rounded to float.</summary>
  public static Matrix4 CreateRotationX(float angle) => (Matrix4)Matrix4d.CreateRotationX(angle);
  /// <summary>A rotation by <paramref name="angle"/> radians about the Y axis, right-handed (z turns towards x);
  /// <see cref="Matrix4d.CreateRotationY(double)"/> rounded to float.</summary>
  public static Matrix4 CreateRotationY(float angle) => (Matrix4)Matrix4d.CreateRotationY(angle);
  /// <summary>A rotation by <paramref name="angle"/> radians about the Z axis, right-handed (x turns towards y);
  /// <see cref="Matrix4d.CreateRotationZ(double)"/> rounded to float.</summary>
  public static Matrix4 CreateRotationZ(float angle) => (Matrix4)Matrix4d.CreateRotationZ(angle);
  /// <summary>A right-handed rotation by <paramref name="angle"/> radians about <paramref name="axis"/> (normalized
  /// first; a zero axis gives NaN), as <see cref="Matrix4d.CreateFromAxisAngle(Vector3d, double)"/>.</summary>
  public static Matrix4 CreateFromAxisAngle(Vector3 axis, float angle) => (Matrix4)Matrix4d.CreateFromAxisAngle(axis, angle);
  /// <summary>An OpenGL-style perspective projection (the eye looks down −z; depth maps onto [−1, 1]) for row vectors.
  /// <param name="fovy">The vertical field of view in radians, in (0, π].</param>
  /// <param name="aspect">Width over height, positive.</param>
  /// <param name="near">The near plane distance, 0 &lt; near &lt; far.</param>
  /// <param name="far">The far plane distance.</param>
  /// <exception cref="System.ArgumentOutOfRangeException">A parameter is outside its range.</exception></summary>
  public static Matrix4 CreatePerspectiveFieldOfView(float fovy, float aspect, float near, float far) =>
    (Matrix4)Matrix4d.CreatePerspectiveFieldOfView(fovy, aspect, near, far);
  /// <summary>World-to-eye matrix of a camera at <paramref name="eye"/> looking at <paramref name="target"/> with
  /// <paramref name="up"/> roughly up, as <see cref="Matrix4d.LookAt(Vector3d, Vector3d, Vector3d)"/> (the eye looks
  /// down its −z); up parallel to the view direction gives NaN.</summary>
  public static Matrix4 LookAt(Vector3 eye, Vector3 target, Vector3 up) => (Matrix4)Matrix4d.LookAt(eye, target, up);

  // OpenTK 3's older names.
  /// <summary>OpenTK 3's name of <see cref="CreateScale(float)"/>.</summary>
  public static Matrix4 Scale(float s) => CreateScale(s);
  /// <summary>OpenTK 3's name of <see cref="CreateScale(float, float, float)"/>.</summary>
  public static Matrix4 Scale(float x, float y, float z) => CreateScale(x, y, z);
  /// <summary>OpenTK 3's name of <see cref="CreateScale(Vector3)"/>.</summary>
  public static Matrix4 Scale(Vector3 s) => CreateScale(s);
  /// <summary>OpenTK 3's name of <see cref="CreateRotationX(float)"/> (radians).</summary>
  public static Matrix4 RotateX(float angle) => CreateRotationX(angle);
  /// <summary>OpenTK 3's name of <see cref="CreateRotationY(float)"/> (radians).</summary>
  public static Matrix4 RotateY(float angle) => CreateRotationY(angle);
  /// <summary>OpenTK 3's name of <see cref="CreateRotationZ(float)"/> (radians).</summary>
  public static Matrix4 RotateZ(float angle) => CreateRotationZ(angle);
  /// <summary>OpenTK 3's name of <see cref="CreateFromAxisAngle(Vector3, float)"/> (radians).</summary>
  public static Matrix4 Rotate(Vector3 axis, float angle) => CreateFromAxisAngle(axis, angle);
  /// <summary>OpenTK 3's name of <see cref="CreateTranslation(Vector3)"/>.</summary>
  public static Matrix4 Translation(Vector3 v) => CreateTranslation(v);
  /// <summary>OpenTK 3's name of <see cref="CreateTranslation(float, float, float)"/>.</summary>
  public static Matrix4 Translation(float x, float y, float z) => CreateTranslation(x, y, z);

  /// <summary>The matrix product, as the <c>*</c> operator: with row vectors, v · (A · B) applies A first, then
  /// B.</summary>
  public static Matrix4 Mult(Matrix4 a, Matrix4 b) => a * b;
  /// <summary>The matrix product A · B (each row of A times B); with row vectors, v · (A · B) applies A first, then
  /// B.</summary>
  public static Matrix4 operator *(Matrix4 a, Matrix4 b) => new(a.Row0 * b, a.Row1 * b, a.Row2 * b, a.Row3 * b);
  /// <summary>Whether the two are equal, as <see cref="Equals(Matrix4)"/> compares them.</summary>
  public static bool operator ==(Matrix4 a, Matrix4 b) => a.Equals(b);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Matrix4)"/>.</summary>
  public static bool operator !=(Matrix4 a, Matrix4 b) => !a.Equals(b);

  /// <summary>The transpose: rows and columns swapped.</summary>
  public static Matrix4 Transpose(Matrix4 m) => new(m.Column0, m.Column1, m.Column2, m.Column3);
  /// <summary>Transposes the matrix in place.</summary>
  public void Transpose() => this = Transpose(this);
  /// <summary>A transposed copy.</summary>
  public readonly Matrix4 Transposed() => Transpose(this);
  /// <exception cref="InvalidOperationException">The matrix is singular (its cofactor determinant is 0).</exception>
  public static Matrix4 Invert(Matrix4 m) => Inverse(m);
  /// <summary>Replaces the matrix by its inverse; a singular matrix throws
  /// <see cref="System.InvalidOperationException"/>.</summary>
  public void Invert() => this = Invert(this);
  /// <summary>The inverse, or (as in OpenTK 3) the matrix unchanged when its determinant is 0.</summary>
  public readonly Matrix4 Inverted() => Determinant == 0 ? this : Invert(this);

  /// <summary>Whether every row equals the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Matrix4 other) => Row0 == other.Row0 && Row1 == other.Row1 && Row2 == other.Row2 && Row3 == other.Row3;
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Matrix4 m && Equals(m);
  /// <inheritdoc/>
  public override readonly int GetHashCode() => HashCode.Combine(Row0, Row1, Row2, Row3);
  /// <inheritdoc/>
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "{0}\n{1}\n{2}\n{3}", Row0, Row1, Row2, Row3);
}
