namespace OpenTK.Mathematics;

// OpenTK 3's remaining members of Matrix4d: the out-parameter creators, Add/Subtract, and the
// decomposition helpers (rotation as a quaternion, projection column).
public partial struct Matrix4d
{
  /// <summary><see cref="CreateFromAxisAngle(Vector3d, double)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CreateFromAxisAngle(Vector3d axis, double angle, out Matrix4d result) => result = CreateFromAxisAngle(axis, angle);
  /// <summary><see cref="CreateRotationX(double)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateRotationX(double angle, out Matrix4d result) => result = CreateRotationX(angle);
  /// <summary><see cref="CreateRotationY(double)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateRotationY(double angle, out Matrix4d result) => result = CreateRotationY(angle);
  /// <summary><see cref="CreateRotationZ(double)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateRotationZ(double angle, out Matrix4d result) => result = CreateRotationZ(angle);
  /// <summary><see cref="CreateTranslation(double, double, double)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CreateTranslation(double x, double y, double z, out Matrix4d result) => result = CreateTranslation(x, y, z);
  /// <summary><see cref="CreateOrthographic(double, double, double, double)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CreateOrthographic(double width, double height, double zNear, double zFar, out Matrix4d result) =>
    result = CreateOrthographic(width, height, zNear, zFar);
  /// <summary><see cref="CreateOrthographicOffCenter(double, double, double, double, double, double)"/>, with the
  /// result written to <paramref name="result"/>.</summary>
  public static void CreateOrthographicOffCenter(double left, double right, double bottom, double top, double zNear, double zFar, out Matrix4d result) =>
    result = CreateOrthographicOffCenter(left, right, bottom, top, zNear, zFar);
  /// <summary><see cref="CreatePerspectiveFieldOfView(double, double, double, double)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CreatePerspectiveFieldOfView(double fovy, double aspect, double zNear, double zFar, out Matrix4d result) =>
    result = CreatePerspectiveFieldOfView(fovy, aspect, zNear, zFar);
  /// <summary><see cref="CreatePerspectiveOffCenter(double, double, double, double, double, double)"/>, with the result
  /// written to <paramref name="result"/>.</summary>
  public static void CreatePerspectiveOffCenter(double left, double right, double bottom, double top, double zNear, double zFar, out Matrix4d result) =>
    result = CreatePerspectiveOffCenter(left, right, bottom, top, zNear, zFar);
  /// <summary><see cref="CreateFromQuaternion(Quaterniond)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CreateFromQuaternion(in Quaterniond q, out Matrix4d result) => result = CreateFromQuaternion(q);

  /// <summary>OpenTK 3's older name of <see cref="CreatePerspectiveOffCenter(double, double, double, double, double, double)"/>.</summary>
  public static Matrix4d Frustum(double left, double right, double bottom, double top, double near, double far) =>
    CreatePerspectiveOffCenter(left, right, bottom, top, near, far);

  /// <summary>The sum, element by element.</summary>
  public static Matrix4d Add(Matrix4d left, Matrix4d right) => left + right;
  /// <summary><see cref="Add(Matrix4d, Matrix4d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Add(in Matrix4d left, in Matrix4d right, out Matrix4d result) => result = left + right;
  /// <summary>The difference, element by element.</summary>
  public static Matrix4d Subtract(Matrix4d left, Matrix4d right) => left - right;
  /// <summary><see cref="Subtract(Matrix4d, Matrix4d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Subtract(in Matrix4d left, in Matrix4d right, out Matrix4d result) => result = left - right;
  /// <summary>Every element multiplied by the scalar.</summary>
  public static Matrix4d Mult(Matrix4d left, double right) => left * right;
  /// <summary><see cref="Mult(Matrix4d, double)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Mult(in Matrix4d left, double right, out Matrix4d result) => result = left * right;
  /// <summary><see cref="Transpose(Matrix4d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Transpose(in Matrix4d mat, out Matrix4d result) => result = Transpose(mat);

  /// <summary>OpenTK's "normalisation": every element divided by the determinant.</summary>
  public void Normalize()
  {
    double d = Determinant;
    Row0 /= d; Row1 /= d; Row2 /= d; Row3 /= d;
  }

  /// <summary>A copy with every element divided by the determinant (OpenTK's "normalisation", see
  /// <see cref="Normalize()"/>).</summary>
  public readonly Matrix4d Normalized() { Matrix4d m = this; m.Normalize(); return m; }

  /// <summary>Keeps each axis's length but drops its direction (a pure scale in the upper 3×3).</summary>
  public readonly Matrix4d ClearRotation()
  {
    Matrix4d m = this;
    m.Row0.Xyz = new Vector3d(Row0.Xyz.Length, 0, 0);
    m.Row1.Xyz = new Vector3d(0, Row1.Xyz.Length, 0);
    m.Row2.Xyz = new Vector3d(0, 0, Row2.Xyz.Length);
    return m;
  }

  /// <summary>Zeroes the last column (the projective part under row vectors).</summary>
  public readonly Matrix4d ClearProjection()
  {
    Matrix4d m = this;
    m.Row0.W = m.Row1.W = m.Row2.W = m.Row3.W = 0;
    return m;
  }

  /// <summary>The last column (the projective part under row vectors).</summary>
  public readonly Vector4d ExtractProjection() => Column3;

  /// <summary>The rotation of the upper 3×3 part; <paramref name="row_normalise"/> first removes a scale.</summary>
  public readonly Quaterniond ExtractRotation(bool row_normalise = true) => new Matrix3d(this).ExtractRotation(row_normalise);
}
