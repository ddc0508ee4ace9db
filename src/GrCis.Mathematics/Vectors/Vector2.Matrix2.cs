namespace OpenTK.Mathematics;

// OpenTK 4's products of Vector2 with a Matrix2 and with a quaternion. "Row" is v · M, "column" is M · v.
public partial struct Vector2
{
  public static Vector2 TransformRow(Vector2 vec, Matrix2 mat) => new(
    vec.X * mat.Row0.X + vec.Y * mat.Row1.X,
    vec.X * mat.Row0.Y + vec.Y * mat.Row1.Y);
  public static void TransformRow(in Vector2 vec, in Matrix2 mat, out Vector2 result) => result = TransformRow(vec, mat);
  public static Vector2 TransformColumn(Matrix2 mat, Vector2 vec) => new(
    vec.X * mat.Row0.X + vec.Y * mat.Row0.Y,
    vec.X * mat.Row1.X + vec.Y * mat.Row1.Y);
  public static void TransformColumn(in Matrix2 mat, in Vector2 vec, out Vector2 result) => result = TransformColumn(mat, vec);
  public static Vector2 operator *(Vector2 vec, Matrix2 mat) => TransformRow(vec, mat);
  public static Vector2 operator *(Matrix2 mat, Vector2 vec) => TransformColumn(mat, vec);
  /// <summary>Rotates (x, y, 0) by the quaternion and keeps x and y, as <see cref="Transform(Vector2, Quaternion)"/>.</summary>
  public static Vector2 operator *(Quaternion quat, Vector2 vec) => Transform(vec, quat);
}
