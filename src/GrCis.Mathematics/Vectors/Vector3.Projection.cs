namespace OpenTK.Mathematics;

// OpenTK 3's remaining transforms of Vector3: by a float Matrix4 (row vectors) with the perspective divide, the
// viewport projection, the rotation by a float Quaternion, and the products with a float Matrix3.
public partial struct Vector3
{
  /// <summary><see cref="TransformNormalInverse(Vector3, Matrix4)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void TransformNormalInverse(in Vector3 norm, in Matrix4 invMat, out Vector3 result) => result = TransformNormalInverse(norm, invMat);

  /// <summary>The point (w = 1) times the matrix, divided by the resulting w.</summary>
  public static Vector3 TransformPerspective(Vector3 vec, Matrix4 mat)
  {
    Vector4 h = Vector4.Transform(new Vector4(vec, 1f), mat);
    return new Vector3(h.X, h.Y, h.Z) / h.W;
  }

  /// <summary><see cref="TransformPerspective(Vector3, Matrix4)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void TransformPerspective(in Vector3 vec, in Matrix4 mat, out Vector3 result) => result = TransformPerspective(vec, mat);

  /// <summary>
  /// World to window coordinates: the point through <paramref name="worldViewProjection"/> and the perspective
  /// divide, then x, y from [−1, 1] onto the viewport rectangle and z onto [minZ, maxZ].
  /// </summary>
  public static Vector3 Project(Vector3 vector, float x, float y, float width, float height, float minZ, float maxZ, Matrix4 worldViewProjection)
  {
    Vector3 ndc = TransformPerspective(vector, worldViewProjection);
    return new Vector3(
      x + width * (ndc.X + 1f) * 0.5f,
      y + height * (ndc.Y + 1f) * 0.5f,
      minZ + (maxZ - minZ) * (ndc.Z + 1f) * 0.5f);
  }

  /// <summary>
  /// Window to world coordinates, the inverse of <see cref="Project"/> given the inverted matrix. As in OpenTK 3,
  /// depth is read as <c>z / (maxZ − minZ)</c> (minZ is not subtracted), so it is exact for minZ = 0.
  /// </summary>
  public static Vector3 Unproject(Vector3 vector, float x, float y, float width, float height, float minZ, float maxZ, Matrix4 inverseWorldViewProjection)
  {
    Vector3 ndc = new(
      (vector.X - x) / width * 2f - 1f,
      (vector.Y - y) / height * 2f - 1f,
      vector.Z / (maxZ - minZ) * 2f - 1f);
    return TransformPerspective(ndc, inverseWorldViewProjection);
  }

  /// <summary>Rotates the vector by a unit quaternion.</summary>
  public static Vector3 Transform(Vector3 vec, Quaternion quat)
  {
    Vector3 u = quat.Xyz, t = 2f * Cross(u, vec);
    return vec + quat.W * t + Cross(u, t);
  }

  /// <summary><see cref="Transform(Vector3, Quaternion)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Transform(in Vector3 vec, in Quaternion quat, out Vector3 result) => result = Transform(vec, quat);
  /// <summary>The vector rotated by the unit quaternion, as <see cref="Transform(Vector3, Quaternion)"/>.</summary>
  public static Vector3 operator *(Quaternion quat, Vector3 vec) => Transform(vec, quat);

  // By a Matrix3, in float and in OpenTK's order of terms. "Row" is v · M (this port's convention), "column" is M · v.
  // Kept as OpenTK 3.3.3 has them: Transform(Matrix3, Vector3) is v · M, while its ref twin is M · v, and
  // TransformRow(Vector3, Matrix3) is M · v, while its ref twin is v · M (OpenTK 4 made TransformRow v · M).
  static Vector3 RowTimes(Vector3 v, Matrix3 m) => new(
    v.X * m.Row0.X + v.Y * m.Row1.X + v.Z * m.Row2.X,
    v.X * m.Row0.Y + v.Y * m.Row1.Y + v.Z * m.Row2.Y,
    v.X * m.Row0.Z + v.Y * m.Row1.Z + v.Z * m.Row2.Z);

  static Vector3 TimesColumn(Matrix3 m, Vector3 v) => new(Dot(m.Row0, v), Dot(m.Row1, v), Dot(m.Row2, v));

  /// <summary>The row vector times the matrix, <c>vec * mat</c>.</summary>
  public static Vector3 Transform(Vector3 vec, Matrix3 mat) => RowTimes(vec, mat);
  /// <summary><see cref="Transform(Vector3, Matrix3)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Transform(in Vector3 vec, in Matrix3 mat, out Vector3 result) => result = RowTimes(vec, mat);
  /// <summary>v · M despite the order of the arguments (OpenTK 3 marks it obsolete for that); see <see cref="TransformColumn(Matrix3, Vector3)"/>.</summary>
  public static Vector3 Transform(Matrix3 mat, Vector3 vec) => RowTimes(vec, mat);
  /// <summary>M · v, unlike <see cref="Transform(Matrix3, Vector3)"/>: OpenTK 3's ref twin disagrees with it.</summary>
  public static void Transform(in Matrix3 mat, in Vector3 vec, out Vector3 result) => result = TimesColumn(mat, vec);
  /// <summary>The matrix times the column vector, <c>mat * vec</c>: each row of the matrix dotted with the
  /// vector.</summary>
  public static Vector3 TransformColumn(Matrix3 mat, Vector3 vec) => TimesColumn(mat, vec);
  /// <summary><see cref="TransformColumn(Matrix3, Vector3)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void TransformColumn(in Matrix3 mat, in Vector3 vec, out Vector3 result) => result = TimesColumn(mat, vec);
  /// <summary>M · v, as in OpenTK 3.3.3 (a slip there: the ref twin and <c>v * M</c> give v · M).</summary>
  public static Vector3 TransformRow(Vector3 vec, Matrix3 mat) => TimesColumn(mat, vec);
  /// <summary>The row vector times the matrix, v · M, written to <paramref name="result"/>; unlike the value form
  /// <see cref="TransformRow(Vector3, Matrix3)"/> (M · v), as in OpenTK 3.3.3.</summary>
  public static void TransformRow(in Vector3 vec, in Matrix3 mat, out Vector3 result) => result = RowTimes(vec, mat);
  /// <summary>The row vector times the matrix, v · M.</summary>
  public static Vector3 operator *(Vector3 vec, Matrix3 mat) => RowTimes(vec, mat);
  /// <summary>The matrix times the column vector, M · v.</summary>
  public static Vector3 operator *(Matrix3 mat, Vector3 vec) => TimesColumn(mat, vec);
}
