namespace OpenTK.Mathematics;

// OpenTK 4's products of Vector2 with a Matrix2 and with a quaternion. "Row" is v · M, "column" is M · v.
public partial struct Vector2
{
  /// <summary>The row vector times the matrix, <c>vec * mat</c>.</summary>
  public static Vector2 TransformRow(Vector2 vec, Matrix2 mat) => new(
    vec.X * mat.Row0.X + vec.Y * mat.Row1.X,
    vec.X * mat.Row0.Y + vec.Y * mat.Row1.Y);
  /// <summary><see cref="TransformRow(Vector2, Matrix2)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void TransformRow(in Vector2 vec, in Matrix2 mat, out Vector2 result) => result = TransformRow(vec, mat);
  /// <summary>The matrix times the column vector, <c>mat * vec</c>.</summary>
  public static Vector2 TransformColumn(Matrix2 mat, Vector2 vec) => new(
    vec.X * mat.Row0.X + vec.Y * mat.Row0.Y,
    vec.X * mat.Row1.X + vec.Y * mat.Row1.Y);
  /// <summary><see cref="TransformColumn(Matrix2, Vector2)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void TransformColumn(in Matrix2 mat, in Vector2 vec, out Vector2 result) => result = TransformColumn(mat, vec);
  /// <summary>The row vector times the matrix, v · M.</summary>
  public static Vector2 operator *(Vector2 vec, Matrix2 mat) => TransformRow(vec, mat);
  /// <summary>The matrix times the column vector, M · v.</summary>
  public static Vector2 operator *(Matrix2 mat, Vector2 vec) => TransformColumn(mat, vec);
  /// <summary>Rotates (x, y, 0) by the quaternion and keeps x and y, as <see cref="Transform(Vector2, Quaternion)"/>.</summary>
  public static Vector2 operator *(Quaternion quat, Vector2 vec) => Transform(vec, quat);
}
