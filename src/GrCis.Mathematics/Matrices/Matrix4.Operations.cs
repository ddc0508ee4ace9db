namespace OpenTK.Mathematics;

// OpenTK 3's remaining static members of the float Matrix4: the out-parameter creators, projections,
// element-wise arithmetic and the ref/out twins. The arithmetic is Matrix4d's, rounded back to float.
public partial struct Matrix4
{
  /// <summary><see cref="CreateFromAxisAngle(Vector3, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CreateFromAxisAngle(Vector3 axis, float angle, out Matrix4 result) => result = CreateFromAxisAngle(axis, angle);
  /// <summary><see cref="CreateRotationX(float)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateRotationX(float angle, out Matrix4 result) => result = CreateRotationX(angle);
  /// <summary><see cref="CreateRotationY(float)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateRotationY(float angle, out Matrix4 result) => result = CreateRotationY(angle);
  /// <summary><see cref="CreateRotationZ(float)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateRotationZ(float angle, out Matrix4 result) => result = CreateRotationZ(angle);
  /// <summary><see cref="CreateScale(float)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateScale(float scale, out Matrix4 result) => result = CreateScale(scale);
  /// <summary><see cref="CreateScale(float, float, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CreateScale(float x, float y, float z, out Matrix4 result) => result = CreateScale(x, y, z);
  /// <summary><see cref="CreateScale(Vector3)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateScale(in Vector3 scale, out Matrix4 result) => result = CreateScale(scale);
  /// <summary><see cref="CreateTranslation(float, float, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CreateTranslation(float x, float y, float z, out Matrix4 result) => result = CreateTranslation(x, y, z);
  /// <summary><see cref="CreateTranslation(Vector3)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateTranslation(in Vector3 vector, out Matrix4 result) => result = CreateTranslation(vector);

  /// <summary>An OpenGL-style orthographic projection of the box [−width/2, width/2] × [−height/2, height/2] between
  /// the depths <paramref name="zNear"/> and <paramref name="zFar"/> (the eye looks down −z) onto the cube [−1,
  /// 1]³.</summary>
  public static Matrix4 CreateOrthographic(float width, float height, float zNear, float zFar) =>
    (Matrix4)Matrix4d.CreateOrthographic(width, height, zNear, zFar);
  /// <summary><see cref="CreateOrthographic(float, float, float, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CreateOrthographic(float width, float height, float zNear, float zFar, out Matrix4 result) =>
    result = CreateOrthographic(width, height, zNear, zFar);
  /// <summary>An OpenGL-style orthographic projection of the box [left, right] × [bottom, top] between the depths
  /// <paramref name="zNear"/> and <paramref name="zFar"/> (the eye looks down −z) onto the cube [−1, 1]³; the offset is
  /// in Row3.</summary>
  public static Matrix4 CreateOrthographicOffCenter(float left, float right, float bottom, float top, float zNear, float zFar) =>
    (Matrix4)Matrix4d.CreateOrthographicOffCenter(left, right, bottom, top, zNear, zFar);
  /// <summary><see cref="CreateOrthographicOffCenter(float, float, float, float, float, float)"/>, with the result
  /// written to <paramref name="result"/>.</summary>
  public static void CreateOrthographicOffCenter(float left, float right, float bottom, float top, float zNear, float zFar, out Matrix4 result) =>
    result = CreateOrthographicOffCenter(left, right, bottom, top, zNear, zFar);
  /// <summary><see cref="CreatePerspectiveFieldOfView(float, float, float, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CreatePerspectiveFieldOfView(float fovy, float aspect, float zNear, float zFar, out Matrix4 result) =>
    result = CreatePerspectiveFieldOfView(fovy, aspect, zNear, zFar);
  /// <summary>An OpenGL-style perspective projection of the frustum whose near-plane rectangle is [left, right] ×
  /// [bottom, top] at the near distance (the eye looks down −z; depth maps onto [−1, 1]), for row vectors. No argument
  /// is checked.</summary>
  public static Matrix4 CreatePerspectiveOffCenter(float left, float right, float bottom, float top, float zNear, float zFar) =>
    (Matrix4)Matrix4d.CreatePerspectiveOffCenter(left, right, bottom, top, zNear, zFar);
  /// <summary><see cref="CreatePerspectiveOffCenter(float, float, float, float, float, float)"/>, with the result
  /// written to <paramref name="result"/>.</summary>
  public static void CreatePerspectiveOffCenter(float left, float right, float bottom, float top, float zNear, float zFar, out Matrix4 result) =>
    result = CreatePerspectiveOffCenter(left, right, bottom, top, zNear, zFar);

  /// <summary><see cref="LookAt(Vector3, Vector3, Vector3)"/> with the eye, target and up vectors given by their
  /// components.</summary>
  public static Matrix4 LookAt(float eyeX, float eyeY, float eyeZ, float targetX, float targetY, float targetZ, float upX, float upY, float upZ) =>
    LookAt(new Vector3(eyeX, eyeY, eyeZ), new Vector3(targetX, targetY, targetZ), new Vector3(upX, upY, upZ));

  /// <summary>The sum, element by element.</summary>
  public static Matrix4 operator +(Matrix4 a, Matrix4 b) => new(a.Row0 + b.Row0, a.Row1 + b.Row1, a.Row2 + b.Row2, a.Row3 + b.Row3);
  /// <summary>The difference, element by element.</summary>
  public static Matrix4 operator -(Matrix4 a, Matrix4 b) => new(a.Row0 - b.Row0, a.Row1 - b.Row1, a.Row2 - b.Row2, a.Row3 - b.Row3);
  /// <summary>Every element multiplied by the scalar.</summary>
  public static Matrix4 operator *(Matrix4 m, float s) => new(m.Row0 * s, m.Row1 * s, m.Row2 * s, m.Row3 * s);

  /// <summary>The sum, element by element.</summary>
  public static Matrix4 Add(Matrix4 left, Matrix4 right) => left + right;
  /// <summary><see cref="Add(Matrix4, Matrix4)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Add(in Matrix4 left, in Matrix4 right, out Matrix4 result) => result = left + right;
  /// <summary>The difference, element by element.</summary>
  public static Matrix4 Subtract(Matrix4 left, Matrix4 right) => left - right;
  /// <summary><see cref="Subtract(Matrix4, Matrix4)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Subtract(in Matrix4 left, in Matrix4 right, out Matrix4 result) => result = left - right;
  /// <summary>Every element multiplied by the scalar.</summary>
  public static Matrix4 Mult(Matrix4 left, float right) => left * right;
  /// <summary><see cref="Mult(Matrix4, float)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Mult(in Matrix4 left, float right, out Matrix4 result) => result = left * right;
  /// <summary><see cref="Mult(Matrix4, Matrix4)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Mult(in Matrix4 left, in Matrix4 right, out Matrix4 result) => result = left * right;
  /// <summary><see cref="Invert(Matrix4)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Invert(in Matrix4 mat, out Matrix4 result) => result = Invert(mat);
  /// <summary><see cref="Transpose(Matrix4)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Transpose(in Matrix4 mat, out Matrix4 result) => result = Transpose(mat);

  /// <summary>The rotation of <paramref name="q"/> for row vectors (<c>v · M</c> rotates v as q does); q need not be unit length.</summary>
  public static Matrix4 CreateFromQuaternion(Quaternion q)
  {
    float s = 2f / q.LengthSquared;
    float xx = q.X * q.X, yy = q.Y * q.Y, zz = q.Z * q.Z;
    float xy = q.X * q.Y, xz = q.X * q.Z, yz = q.Y * q.Z, xw = q.X * q.W, yw = q.Y * q.W, zw = q.Z * q.W;
    return new Matrix4(
      1f - s * (yy + zz), s * (xy + zw), s * (xz - yw), 0,
      s * (xy - zw), 1f - s * (xx + zz), s * (yz + xw), 0,
      s * (xz + yw), s * (yz - xw), 1f - s * (xx + yy), 0,
      0, 0, 0, 1);
  }

  /// <summary><see cref="CreateFromQuaternion(Quaternion)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CreateFromQuaternion(in Quaternion q, out Matrix4 result) => result = CreateFromQuaternion(q);
}
