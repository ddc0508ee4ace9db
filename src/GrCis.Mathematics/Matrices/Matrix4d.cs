using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>
/// A 4×4 double matrix with OpenTK's layout and names. Row-vector convention: a point is
/// transformed as <c>v * M</c>, translation sits in <see cref="Row3"/>, and <c>A * B</c>
/// applies A first. Includes OpenTK 3 names (Scale, RotateX, Translation) old scripts use.
/// </summary>
[Serializable]
[OpenTk3RefForms]
public partial struct Matrix4d : IEquatable<Matrix4d>
{
  /// <summary>The rows; a point v is transformed as (v, 1) · M, so Row3 holds the translation.</summary>
  public Vector4d Row0, Row1, Row2, Row3;

  /// <summary>The identity matrix.</summary>
  public static readonly Matrix4d Identity = new(Vector4d.UnitX, Vector4d.UnitY, Vector4d.UnitZ, Vector4d.UnitW);
  /// <summary>The matrix with every element 0.</summary>
  public static readonly Matrix4d Zero = new(Vector4d.Zero, Vector4d.Zero, Vector4d.Zero, Vector4d.Zero);

  /// <summary>A 4×4 matrix with <paramref name="topLeft"/> as its rotation/scale part and no translation.</summary>
  public Matrix4d(Matrix3d topLeft)
    : this(new Vector4d(topLeft.Row0, 0), new Vector4d(topLeft.Row1, 0), new Vector4d(topLeft.Row2, 0), Vector4d.UnitW)
  {
  }

  /// <summary>The matrix with the given rows.</summary>
  public Matrix4d(Vector4d row0, Vector4d row1, Vector4d row2, Vector4d row3)
  {
    Row0 = row0; Row1 = row1; Row2 = row2; Row3 = row3;
  }

  /// <summary>The matrix from its elements row by row: m<i>rc</i> is row r, column c (from 0).</summary>
  public Matrix4d(
    double m00, double m01, double m02, double m03,
    double m10, double m11, double m12, double m13,
    double m20, double m21, double m22, double m23,
    double m30, double m31, double m32, double m33)
  {
    Row0 = new Vector4d(m00, m01, m02, m03);
    Row1 = new Vector4d(m10, m11, m12, m13);
    Row2 = new Vector4d(m20, m21, m22, m23);
    Row3 = new Vector4d(m30, m31, m32, m33);
  }

  /// <summary>The element in row 1, column 1 (counted from 1): <c>Row0.X</c>.</summary>
  public double M11 { readonly get => Row0.X; set => Row0.X = value; }
  /// <summary>The element in row 1, column 2 (counted from 1): <c>Row0.Y</c>.</summary>
  public double M12 { readonly get => Row0.Y; set => Row0.Y = value; }
  /// <summary>The element in row 1, column 3 (counted from 1): <c>Row0.Z</c>.</summary>
  public double M13 { readonly get => Row0.Z; set => Row0.Z = value; }
  /// <summary>The element in row 1, column 4 (counted from 1): <c>Row0.W</c>.</summary>
  public double M14 { readonly get => Row0.W; set => Row0.W = value; }
  /// <summary>The element in row 2, column 1 (counted from 1): <c>Row1.X</c>.</summary>
  public double M21 { readonly get => Row1.X; set => Row1.X = value; }
  /// <summary>The element in row 2, column 2 (counted from 1): <c>Row1.Y</c>.</summary>
  public double M22 { readonly get => Row1.Y; set => Row1.Y = value; }
  /// <summary>The element in row 2, column 3 (counted from 1): <c>Row1.Z</c>.</summary>
  public double M23 { readonly get => Row1.Z; set => Row1.Z = value; }
  /// <summary>The element in row 2, column 4 (counted from 1): <c>Row1.W</c>.</summary>
  public double M24 { readonly get => Row1.W; set => Row1.W = value; }
  /// <summary>The element in row 3, column 1 (counted from 1): <c>Row2.X</c>.</summary>
  public double M31 { readonly get => Row2.X; set => Row2.X = value; }
  /// <summary>The element in row 3, column 2 (counted from 1): <c>Row2.Y</c>.</summary>
  public double M32 { readonly get => Row2.Y; set => Row2.Y = value; }
  /// <summary>The element in row 3, column 3 (counted from 1): <c>Row2.Z</c>.</summary>
  public double M33 { readonly get => Row2.Z; set => Row2.Z = value; }
  /// <summary>The element in row 3, column 4 (counted from 1): <c>Row2.W</c>.</summary>
  public double M34 { readonly get => Row2.W; set => Row2.W = value; }
  /// <summary>The element in row 4, column 1 (counted from 1): <c>Row3.X</c>.</summary>
  public double M41 { readonly get => Row3.X; set => Row3.X = value; }
  /// <summary>The element in row 4, column 2 (counted from 1): <c>Row3.Y</c>.</summary>
  public double M42 { readonly get => Row3.Y; set => Row3.Y = value; }
  /// <summary>The element in row 4, column 3 (counted from 1): <c>Row3.Z</c>.</summary>
  public double M43 { readonly get => Row3.Z; set => Row3.Z = value; }
  /// <summary>The element in row 4, column 4 (counted from 1): <c>Row3.W</c>.</summary>
  public double M44 { readonly get => Row3.W; set => Row3.W = value; }

  /// <summary>Column 0: the X of every row (read-only).</summary>
  public readonly Vector4d Column0 => new(Row0.X, Row1.X, Row2.X, Row3.X);
  /// <summary>Column 1: the Y of every row (read-only).</summary>
  public readonly Vector4d Column1 => new(Row0.Y, Row1.Y, Row2.Y, Row3.Y);
  /// <summary>Column 2: the Z of every row (read-only).</summary>
  public readonly Vector4d Column2 => new(Row0.Z, Row1.Z, Row2.Z, Row3.Z);
  /// <summary>Column 3: the W of every row, the projective part under row vectors (read-only).</summary>
  public readonly Vector4d Column3 => new(Row0.W, Row1.W, Row2.W, Row3.W);
  /// <summary>The main diagonal (M11, M22, …); setting writes it back, leaving the other elements.</summary>
  public Vector4d Diagonal { readonly get => new(Row0.X, Row1.Y, Row2.Z, Row3.W); set { Row0.X = value.X; Row1.Y = value.Y; Row2.Z = value.Z; Row3.W = value.W; } }
  /// <summary>The trace: the sum of the diagonal elements.</summary>
  public readonly double Trace => Row0.X + Row1.Y + Row2.Z + Row3.W;

  /// <summary>The element in row <paramref name="row"/>, column <paramref name="column"/> (both 0..3); other indices
  /// throw <see cref="System.IndexOutOfRangeException"/>.</summary>
  public double this[int row, int column]
  {
    readonly get => row switch
    {
      0 => Row0[column], 1 => Row1[column], 2 => Row2[column], 3 => Row3[column],
      _ => throw new IndexOutOfRangeException($"Matrix4d row {row} is outside 0..3."),
    };
    set
    {
      switch (row)
      {
        case 0: Row0[column] = value; break;
        case 1: Row1[column] = value; break;
        case 2: Row2[column] = value; break;
        case 3: Row3[column] = value; break;
        default: throw new IndexOutOfRangeException($"Matrix4d row {row} is outside 0..3.");
      }
    }
  }

  /// <summary>The determinant, by cofactor expansion along the first row.</summary>
  public readonly double Determinant
  {
    get
    {
      double a = Row0.X, b = Row0.Y, c = Row0.Z, d = Row0.W;
      double e = Row1.X, f = Row1.Y, g = Row1.Z, h = Row1.W;
      double i = Row2.X, j = Row2.Y, k = Row2.Z, l = Row2.W;
      double m = Row3.X, n = Row3.Y, o = Row3.Z, p = Row3.W;
      double kp_lo = k * p - l * o, jp_ln = j * p - l * n, jo_kn = j * o - k * n;
      double ip_lm = i * p - l * m, io_km = i * o - k * m, in_jm = i * n - j * m;
      return a * (f * kp_lo - g * jp_ln + h * jo_kn)
           - b * (e * kp_lo - g * ip_lm + h * io_km)
           + c * (e * jp_ln - f * ip_lm + h * in_jm)
           - d * (e * jo_kn - f * io_km + g * in_jm);
    }
  }

  // --- Construction -------------------------------------------------------------------

  /// <summary>A translation by (x, y, z): the identity with Row3 = (x, y, z, 1), for row vectors <c>(v, 1) ·
  /// M</c>.</summary>
  public static Matrix4d CreateTranslation(double x, double y, double z)
  {
    Matrix4d r = Identity;
    r.Row3 = new Vector4d(x, y, z, 1.0);
    return r;
  }

  /// <summary>A translation by <paramref name="v"/>: the identity with Row3 = (v, 1).</summary>
  public static Matrix4d CreateTranslation(Vector3d v) => CreateTranslation(v.X, v.Y, v.Z);
  /// <summary><see cref="CreateTranslation(Vector3d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CreateTranslation(in Vector3d v, out Matrix4d result) => result = CreateTranslation(v);

  /// <summary>A uniform scale by <paramref name="s"/>: the diagonal (s, s, s, 1).</summary>
  public static Matrix4d CreateScale(double s) => CreateScale(s, s, s);
  /// <summary>A scale by the components of <paramref name="s"/> along the axes: the diagonal (s.X, s.Y, s.Z,
  /// 1).</summary>
  public static Matrix4d CreateScale(Vector3d s) => CreateScale(s.X, s.Y, s.Z);

  /// <summary>A scale by x, y and z along the axes: the diagonal (x, y, z, 1).</summary>
  public static Matrix4d CreateScale(double x, double y, double z)
  {
    Matrix4d r = Identity;
    r.Row0.X = x; r.Row1.Y = y; r.Row2.Z = z;
    return r;
  }

  /// <summary>A rotation by <paramref name="angle"/> radians about the X axis, right-handed (y turns towards z), for
  /// row vectors: Row1 = (0, cos, sin, 0), Row2 = (0, −sin, cos, 0).</summary>
  public static Matrix4d CreateRotationX(double angle)
  {
    double c = Math.Cos(angle), s = Math.Sin(angle);
    Matrix4d r = Identity;
    r.Row1 = new Vector4d(0, c, s, 0);
    r.Row2 = new Vector4d(0, -s, c, 0);
    return r;
  }

  /// <summary>A rotation by <paramref name="angle"/> radians about the Y axis, right-handed (z turns towards x), for
  /// row vectors: Row0 = (cos, 0, −sin, 0), Row2 = (sin, 0, cos, 0).</summary>
  public static Matrix4d CreateRotationY(double angle)
  {
    double c = Math.Cos(angle), s = Math.Sin(angle);
    Matrix4d r = Identity;
    r.Row0 = new Vector4d(c, 0, -s, 0);
    r.Row2 = new Vector4d(s, 0, c, 0);
    return r;
  }

  /// <summary>A rotation by <paramref name="angle"/> radians about the Z axis, right-handed (x turns towards y), for
  /// row vectors: Row0 = (cos, sin, 0, 0), Row1 = (−sin, cos, 0, 0).</summary>
  public static Matrix4d CreateRotationZ(double angle)
  {
    double c = Math.Cos(angle), s = Math.Sin(angle);
    Matrix4d r = Identity;
    r.Row0 = new Vector4d(c, s, 0, 0);
    r.Row1 = new Vector4d(-s, c, 0, 0);
    return r;
  }

  /// <summary>Right-handed rotation by <paramref name="angle"/> radians about <paramref name="axis"/>.</summary>
  public static Matrix4d CreateFromAxisAngle(Vector3d axis, double angle)
  {
    axis = axis.Normalized();
    double c = Math.Cos(angle), s = Math.Sin(angle), t = 1.0 - c;
    double x = axis.X, y = axis.Y, z = axis.Z;
    // Rows of the transpose of the column-vector rotation matrix.
    return new Matrix4d(
      t * x * x + c, t * x * y + s * z, t * x * z - s * y, 0,
      t * x * y - s * z, t * y * y + c, t * y * z + s * x, 0,
      t * x * z + s * y, t * y * z - s * x, t * z * z + c, 0,
      0, 0, 0, 1);
  }

  /// <summary>The rotation of the unit quaternion <paramref name="q"/>, built from its axis and angle
  /// (<see cref="Quaterniond.ToAxisAngle(out Vector3d, out double)"/>).</summary>
  public static Matrix4d CreateFromQuaternion(Quaterniond q)
  {
    q.ToAxisAngle(out Vector3d axis, out double angle);
    return axis.LengthSquared == 0.0 ? Identity : CreateFromAxisAngle(axis, angle);
  }

  /// <summary>An OpenGL-style perspective projection (the eye looks down −z; depth maps onto [−1, 1]) for row vectors.
  /// <param name="fovy">The vertical field of view in radians, in (0, π].</param>
  /// <param name="aspect">Width over height, positive.</param>
  /// <param name="near">The near plane distance, 0 &lt; near &lt; far.</param>
  /// <param name="far">The far plane distance.</param>
  /// <exception cref="System.ArgumentOutOfRangeException">A parameter is outside its range.</exception></summary>
  public static Matrix4d CreatePerspectiveFieldOfView(double fovy, double aspect, double near, double far)
  {
    if (fovy <= 0 || fovy > Math.PI) throw new ArgumentOutOfRangeException(nameof(fovy), "Must be in (0, π].");
    if (aspect <= 0) throw new ArgumentOutOfRangeException(nameof(aspect), "Must be positive.");
    if (near <= 0 || far <= near) throw new ArgumentOutOfRangeException(nameof(near), "Need 0 < near < far.");
    double yMax = near * Math.Tan(0.5 * fovy), xMax = yMax * aspect;
    return CreatePerspectiveOffCenter(-xMax, xMax, -yMax, yMax, near, far);
  }

  /// <summary>An OpenGL-style perspective projection of the frustum whose near-plane rectangle is [left, right] ×
  /// [bottom, top] at the near distance (the eye looks down −z; depth maps onto [−1, 1]), for row vectors. No argument
  /// is checked.</summary>
  public static Matrix4d CreatePerspectiveOffCenter(double left, double right, double bottom, double top, double near, double far)
  {
    double x = 2.0 * near / (right - left), y = 2.0 * near / (top - bottom);
    double a = (right + left) / (right - left), b = (top + bottom) / (top - bottom);
    double c = -(far + near) / (far - near), d = -(2.0 * far * near) / (far - near);
    return new Matrix4d(x, 0, 0, 0, 0, y, 0, 0, a, b, c, -1, 0, 0, d, 0);
  }

  /// <summary>An OpenGL-style orthographic projection of the box [−width/2, width/2] × [−height/2, height/2] between
  /// the depths <paramref name="near"/> and <paramref name="far"/> (the eye looks down −z) onto the cube [−1,
  /// 1]³.</summary>
  public static Matrix4d CreateOrthographic(double width, double height, double near, double far) =>
    CreateOrthographicOffCenter(-width / 2, width / 2, -height / 2, height / 2, near, far);

  /// <summary>An OpenGL-style orthographic projection of the box [left, right] × [bottom, top] between the depths
  /// <paramref name="near"/> and <paramref name="far"/> (the eye looks down −z) onto the cube [−1, 1]³; the offset is
  /// in Row3.</summary>
  public static Matrix4d CreateOrthographicOffCenter(double left, double right, double bottom, double top, double near, double far)
  {
    Matrix4d r = Identity;
    r.Row0.X = 2.0 / (right - left);
    r.Row1.Y = 2.0 / (top - bottom);
    r.Row2.Z = -2.0 / (far - near);
    r.Row3 = new Vector4d(-(right + left) / (right - left), -(top + bottom) / (top - bottom), -(far + near) / (far - near), 1);
    return r;
  }

  /// <summary>World-to-eye matrix of a camera at <paramref name="eye"/> looking at <paramref name="target"/>.</summary>
  public static Matrix4d LookAt(Vector3d eye, Vector3d target, Vector3d up)
  {
    Vector3d z = (eye - target).Normalized();
    Vector3d x = Vector3d.Cross(up, z).Normalized();
    Vector3d y = Vector3d.Cross(z, x).Normalized();
    return new Matrix4d(
      x.X, y.X, z.X, 0,
      x.Y, y.Y, z.Y, 0,
      x.Z, y.Z, z.Z, 0,
      -Vector3d.Dot(x, eye), -Vector3d.Dot(y, eye), -Vector3d.Dot(z, eye), 1);
  }

  /// <summary><see cref="LookAt(Vector3d, Vector3d, Vector3d)"/> with the eye, target and up vectors given by their
  /// components.</summary>
  public static Matrix4d LookAt(double eyeX, double eyeY, double eyeZ, double targetX, double targetY, double targetZ, double upX, double upY, double upZ) =>
    LookAt(new Vector3d(eyeX, eyeY, eyeZ), new Vector3d(targetX, targetY, targetZ), new Vector3d(upX, upY, upZ));

  // OpenTK 3 names kept for old scene scripts.
  /// <summary>OpenTK 3's name of <see cref="CreateScale(double)"/>.</summary>
  public static Matrix4d Scale(double s) => CreateScale(s);
  /// <summary>OpenTK 3's name of <see cref="CreateScale(double, double, double)"/>.</summary>
  public static Matrix4d Scale(double x, double y, double z) => CreateScale(x, y, z);
  /// <summary>OpenTK 3's name of <see cref="CreateScale(Vector3d)"/>.</summary>
  public static Matrix4d Scale(Vector3d s) => CreateScale(s);
  /// <summary>OpenTK 3's name of <see cref="CreateRotationX(double)"/> (radians).</summary>
  public static Matrix4d RotateX(double angle) => CreateRotationX(angle);
  /// <summary>OpenTK 3's name of <see cref="CreateRotationY(double)"/> (radians).</summary>
  public static Matrix4d RotateY(double angle) => CreateRotationY(angle);
  /// <summary>OpenTK 3's name of <see cref="CreateRotationZ(double)"/> (radians).</summary>
  public static Matrix4d RotateZ(double angle) => CreateRotationZ(angle);
  /// <summary>OpenTK 3's name of <see cref="CreateFromAxisAngle(Vector3d, double)"/> (radians).</summary>
  public static Matrix4d Rotate(Vector3d axis, double angle) => CreateFromAxisAngle(axis, angle);
  /// <summary>OpenTK 3's name of <see cref="CreateFromQuaternion(Quaterniond)"/>.</summary>
  public static Matrix4d Rotate(Quaterniond q) => CreateFromQuaternion(q);
  /// <summary>OpenTK 3's name of <see cref="CreateTranslation(Vector3d)"/>.</summary>
  public static Matrix4d Translation(Vector3d v) => CreateTranslation(v);
  /// <summary>OpenTK 3's name of <see cref="CreateTranslation(double, double, double)"/>.</summary>
  public static Matrix4d Translation(double x, double y, double z) => CreateTranslation(x, y, z);
  /// <summary>OpenTK 3's name of <see cref="CreatePerspectiveFieldOfView(double, double, double, double)"/>.</summary>
  public static Matrix4d Perspective(double fovy, double aspect, double near, double far) => CreatePerspectiveFieldOfView(fovy, aspect, near, far);

  // --- Arithmetic ----------------------------------------------------------------------

  /// <summary>The matrix product, as the <c>*</c> operator: with row vectors, v · (A · B) applies A first, then
  /// B.</summary>
  public static Matrix4d Mult(Matrix4d a, Matrix4d b) => a * b;
  /// <summary><see cref="Mult(Matrix4d, Matrix4d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Mult(in Matrix4d a, in Matrix4d b, out Matrix4d result) => result = a * b;
  /// <summary>The matrix product, as the <c>*</c> operator: with row vectors, v · (A · B) applies A first, then
  /// B.</summary>
  public static Matrix4d Multiply(Matrix4d a, Matrix4d b) => a * b;

  /// <summary>The matrix product A · B (each row of A times B); with row vectors, v · (A · B) applies A first, then
  /// B.</summary>
  public static Matrix4d operator *(Matrix4d a, Matrix4d b) => new(
    Vector4d.Transform(a.Row0, b), Vector4d.Transform(a.Row1, b),
    Vector4d.Transform(a.Row2, b), Vector4d.Transform(a.Row3, b));

  /// <summary>Every element multiplied by the scalar.</summary>
  public static Matrix4d operator *(Matrix4d a, double s) => new(a.Row0 * s, a.Row1 * s, a.Row2 * s, a.Row3 * s);
  /// <summary>The sum, element by element.</summary>
  public static Matrix4d operator +(Matrix4d a, Matrix4d b) => new(a.Row0 + b.Row0, a.Row1 + b.Row1, a.Row2 + b.Row2, a.Row3 + b.Row3);
  /// <summary>The difference, element by element.</summary>
  public static Matrix4d operator -(Matrix4d a, Matrix4d b) => new(a.Row0 - b.Row0, a.Row1 - b.Row1, a.Row2 - b.Row2, a.Row3 - b.Row3);
  /// <summary>Whether the two are equal, as <see cref="Equals(Matrix4d)"/> compares them.</summary>
  public static bool operator ==(Matrix4d a, Matrix4d b) => a.Equals(b);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Matrix4d)"/>.</summary>
  public static bool operator !=(Matrix4d a, Matrix4d b) => !a.Equals(b);

  /// <summary>The transpose: rows and columns swapped.</summary>
  public static Matrix4d Transpose(Matrix4d m) => new(m.Column0, m.Column1, m.Column2, m.Column3);
  /// <summary>Transposes the matrix in place.</summary>
  public void Transpose() => this = Transpose(this);
  /// <summary>A transposed copy.</summary>
  public readonly Matrix4d Transposed() => Transpose(this);

  /// <summary>Inverse by Gauss–Jordan elimination with partial pivoting.</summary>
  /// <exception cref="InvalidOperationException">The matrix is singular.</exception>
  public static Matrix4d Invert(Matrix4d m)
  {
    Span<double> a = stackalloc double[16];
    Span<double> inv = stackalloc double[16];
    for (int r = 0; r < 4; r++)
      for (int c = 0; c < 4; c++)
      {
        a[r * 4 + c] = m[r, c];
        inv[r * 4 + c] = r == c ? 1.0 : 0.0;
      }

    for (int col = 0; col < 4; col++)
    {
      int pivot = col;
      double best = Math.Abs(a[col * 4 + col]);
      for (int r = col + 1; r < 4; r++)
      {
        double v = Math.Abs(a[r * 4 + col]);
        if (v > best) { best = v; pivot = r; }
      }
      if (best == 0.0 || double.IsNaN(best))
        throw new InvalidOperationException("Matrix is singular and cannot be inverted.");
      if (pivot != col)
        for (int c = 0; c < 4; c++)
        {
          (a[col * 4 + c], a[pivot * 4 + c]) = (a[pivot * 4 + c], a[col * 4 + c]);
          (inv[col * 4 + c], inv[pivot * 4 + c]) = (inv[pivot * 4 + c], inv[col * 4 + c]);
        }
      double d = 1.0 / a[col * 4 + col];
      for (int c = 0; c < 4; c++) { a[col * 4 + c] *= d; inv[col * 4 + c] *= d; }
      for (int r = 0; r < 4; r++)
      {
        if (r == col) continue;
        double f = a[r * 4 + col];
        if (f == 0.0) continue;
        for (int c = 0; c < 4; c++)
        {
          a[r * 4 + c] -= f * a[col * 4 + c];
          inv[r * 4 + c] -= f * inv[col * 4 + c];
        }
      }
    }

    Matrix4d result = default;
    for (int r = 0; r < 4; r++)
      for (int c = 0; c < 4; c++)
        result[r, c] = inv[r * 4 + c];
    return result;
  }

  /// <summary><see cref="Invert(Matrix4d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Invert(in Matrix4d m, out Matrix4d result) => result = Invert(m);
  /// <summary>Replaces the matrix by its inverse; a singular matrix throws
  /// <see cref="System.InvalidOperationException"/>.</summary>
  public void Invert() => this = Invert(this);
  /// <summary>The inverse, or (as in OpenTK 3) the matrix unchanged when its determinant is 0; <see cref="Invert(Matrix4d)"/> throws then.</summary>
  public readonly Matrix4d Inverted() => Determinant == 0 ? this : Invert(this);

  /// <summary>The translation: x, y, z of Row3.</summary>
  public readonly Vector3d ExtractTranslation() => Row3.Xyz;
  /// <summary>The scale along each axis: the lengths of the x, y, z parts of the first three rows.</summary>
  public readonly Vector3d ExtractScale() => new(Row0.Xyz.Length, Row1.Xyz.Length, Row2.Xyz.Length);
  /// <summary>A copy with the translation (x, y, z of Row3) set to zero.</summary>
  public readonly Matrix4d ClearTranslation() { Matrix4d r = this; r.Row3.Xyz = Vector3d.Zero; return r; }
  /// <summary>The x, y, z part of each of the first three rows made unit length: the rotation (and translation) without
  /// the scale.</summary>
  public readonly Matrix4d ClearScale()
  {
    Matrix4d r = this;
    r.Row0.Xyz = r.Row0.Xyz.Normalized(); r.Row1.Xyz = r.Row1.Xyz.Normalized(); r.Row2.Xyz = r.Row2.Xyz.Normalized();
    return r;
  }

  /// <summary>Whether every row equals the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Matrix4d other) => Row0 == other.Row0 && Row1 == other.Row1 && Row2 == other.Row2 && Row3 == other.Row3;
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Matrix4d m && Equals(m);
  /// <inheritdoc/>
  public override readonly int GetHashCode() => HashCode.Combine(Row0, Row1, Row2, Row3);
  /// <inheritdoc/>
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "{0}\n{1}\n{2}\n{3}", Row0, Row1, Row2, Row3);
}
