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
  public Vector4 Row0, Row1, Row2, Row3;

  public static readonly Matrix4 Identity = new(new Vector4(1, 0, 0, 0), new Vector4(0, 1, 0, 0), new Vector4(0, 0, 1, 0), new Vector4(0, 0, 0, 1));
  public static readonly Matrix4 Zero = new(Vector4.Zero, Vector4.Zero, Vector4.Zero, Vector4.Zero);

  public Matrix4(Vector4 row0, Vector4 row1, Vector4 row2, Vector4 row3) => (Row0, Row1, Row2, Row3) = (row0, row1, row2, row3);

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

  public float M11 { readonly get => Row0.X; set => Row0.X = value; }
  public float M12 { readonly get => Row0.Y; set => Row0.Y = value; }
  public float M13 { readonly get => Row0.Z; set => Row0.Z = value; }
  public float M14 { readonly get => Row0.W; set => Row0.W = value; }
  public float M21 { readonly get => Row1.X; set => Row1.X = value; }
  public float M22 { readonly get => Row1.Y; set => Row1.Y = value; }
  public float M23 { readonly get => Row1.Z; set => Row1.Z = value; }
  public float M24 { readonly get => Row1.W; set => Row1.W = value; }
  public float M31 { readonly get => Row2.X; set => Row2.X = value; }
  public float M32 { readonly get => Row2.Y; set => Row2.Y = value; }
  public float M33 { readonly get => Row2.Z; set => Row2.Z = value; }
  public float M34 { readonly get => Row2.W; set => Row2.W = value; }
  public float M41 { readonly get => Row3.X; set => Row3.X = value; }
  public float M42 { readonly get => Row3.Y; set => Row3.Y = value; }
  public float M43 { readonly get => Row3.Z; set => Row3.Z = value; }
  public float M44 { readonly get => Row3.W; set => Row3.W = value; }

  public static explicit operator Matrix4(Matrix4d m) => new((Vector4)m.Row0, (Vector4)m.Row1, (Vector4)m.Row2, (Vector4)m.Row3);

  public static implicit operator Matrix4d(Matrix4 m) => new(m.Row0, m.Row1, m.Row2, m.Row3);

  public static Matrix4 CreateTranslation(float x, float y, float z) => (Matrix4)Matrix4d.CreateTranslation(x, y, z);
  public static Matrix4 CreateTranslation(Vector3 v) => CreateTranslation(v.X, v.Y, v.Z);
  public static Matrix4 CreateScale(float s) => (Matrix4)Matrix4d.CreateScale(s);
  public static Matrix4 CreateScale(float x, float y, float z) => (Matrix4)Matrix4d.CreateScale(x, y, z);
  public static Matrix4 CreateScale(Vector3 s) => CreateScale(s.X, s.Y, s.Z);
  public static Matrix4 CreateRotationX(float angle) => (Matrix4)Matrix4d.CreateRotationX(angle);
  public static Matrix4 CreateRotationY(float angle) => (Matrix4)Matrix4d.CreateRotationY(angle);
  public static Matrix4 CreateRotationZ(float angle) => (Matrix4)Matrix4d.CreateRotationZ(angle);
  public static Matrix4 CreateFromAxisAngle(Vector3 axis, float angle) => (Matrix4)Matrix4d.CreateFromAxisAngle(axis, angle);
  public static Matrix4 CreatePerspectiveFieldOfView(float fovy, float aspect, float near, float far) =>
    (Matrix4)Matrix4d.CreatePerspectiveFieldOfView(fovy, aspect, near, far);
  public static Matrix4 LookAt(Vector3 eye, Vector3 target, Vector3 up) => (Matrix4)Matrix4d.LookAt(eye, target, up);

  // OpenTK 3's older names.
  public static Matrix4 Scale(float s) => CreateScale(s);
  public static Matrix4 Scale(float x, float y, float z) => CreateScale(x, y, z);
  public static Matrix4 Scale(Vector3 s) => CreateScale(s);
  public static Matrix4 RotateX(float angle) => CreateRotationX(angle);
  public static Matrix4 RotateY(float angle) => CreateRotationY(angle);
  public static Matrix4 RotateZ(float angle) => CreateRotationZ(angle);
  public static Matrix4 Rotate(Vector3 axis, float angle) => CreateFromAxisAngle(axis, angle);
  public static Matrix4 Translation(Vector3 v) => CreateTranslation(v);
  public static Matrix4 Translation(float x, float y, float z) => CreateTranslation(x, y, z);

  public static Matrix4 Mult(Matrix4 a, Matrix4 b) => a * b;
  public static Matrix4 operator *(Matrix4 a, Matrix4 b) => new(a.Row0 * b, a.Row1 * b, a.Row2 * b, a.Row3 * b);
  public static bool operator ==(Matrix4 a, Matrix4 b) => a.Equals(b);
  public static bool operator !=(Matrix4 a, Matrix4 b) => !a.Equals(b);

  public static Matrix4 Transpose(Matrix4 m) => new(m.Column0, m.Column1, m.Column2, m.Column3);
  public void Transpose() => this = Transpose(this);
  public readonly Matrix4 Transposed() => Transpose(this);
  /// <exception cref="InvalidOperationException">The matrix is singular (its cofactor determinant is 0).</exception>
  public static Matrix4 Invert(Matrix4 m) => Inverse(m);
  public void Invert() => this = Invert(this);
  /// <summary>The inverse, or (as in OpenTK 3) the matrix unchanged when its determinant is 0.</summary>
  public readonly Matrix4 Inverted() => Determinant == 0 ? this : Invert(this);

  public readonly bool Equals(Matrix4 other) => Row0 == other.Row0 && Row1 == other.Row1 && Row2 == other.Row2 && Row3 == other.Row3;
  public override readonly bool Equals(object? obj) => obj is Matrix4 m && Equals(m);
  public override readonly int GetHashCode() => HashCode.Combine(Row0, Row1, Row2, Row3);
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "{0}\n{1}\n{2}\n{3}", Row0, Row1, Row2, Row3);
}
