namespace OpenTK.Mathematics;

// OpenTK 3's remaining transforms of Vector3: by a float Matrix4 (row vectors) with the perspective divide, the
// viewport projection, and the rotation by a float Quaternion.
public partial struct Vector3
{
  public static void TransformNormalInverse(ref Vector3 norm, ref Matrix4 invMat, out Vector3 result) => result = TransformNormalInverse(norm, invMat);

  /// <summary>The point (w = 1) times the matrix, divided by the resulting w.</summary>
  public static Vector3 TransformPerspective(Vector3 vec, Matrix4 mat)
  {
    Vector4 h = Vector4.Transform(new Vector4(vec, 1f), mat);
    return new Vector3(h.X, h.Y, h.Z) / h.W;
  }

  public static void TransformPerspective(ref Vector3 vec, ref Matrix4 mat, out Vector3 result) => result = TransformPerspective(vec, mat);

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

  public static void Transform(ref Vector3 vec, ref Quaternion quat, out Vector3 result) => result = Transform(vec, quat);
  public static Vector3 operator *(Quaternion quat, Vector3 vec) => Transform(vec, quat);
}
