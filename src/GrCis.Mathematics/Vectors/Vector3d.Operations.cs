using System.Runtime.CompilerServices;

namespace OpenTK.Mathematics;

// OpenTK 3's remaining members of Vector3d: mostly the ref/out twins of the static helpers.
public partial struct Vector3d
{
  public static readonly int SizeInBytes = Unsafe.SizeOf<Vector3d>();

  /// <summary>(x, y, 0).</summary>
  public Vector3d(Vector2d v) { X = v.X; Y = v.Y; Z = 0; }

  public static void Add(in Vector3d a, in Vector3d b, out Vector3d result) => result = a + b;
  public static void Subtract(in Vector3d a, in Vector3d b, out Vector3d result) => result = a - b;
  public static void Multiply(in Vector3d vector, double scale, out Vector3d result) => result = vector * scale;
  public static void Multiply(in Vector3d vector, in Vector3d scale, out Vector3d result) => result = vector * scale;
  public static void Divide(in Vector3d vector, double scale, out Vector3d result) => result = vector / scale;
  public static void Divide(in Vector3d vector, in Vector3d scale, out Vector3d result) => result = vector / scale;
  public static void ComponentMin(in Vector3d a, in Vector3d b, out Vector3d result) => result = ComponentMin(a, b);
  public static void ComponentMax(in Vector3d a, in Vector3d b, out Vector3d result) => result = ComponentMax(a, b);
  public static Vector3d MagnitudeMin(Vector3d left, Vector3d right) => left.LengthSquared < right.LengthSquared ? left : right;
  public static void MagnitudeMin(in Vector3d left, in Vector3d right, out Vector3d result) => result = MagnitudeMin(left, right);
  public static Vector3d MagnitudeMax(Vector3d left, Vector3d right) => left.LengthSquared >= right.LengthSquared ? left : right;
  public static void MagnitudeMax(in Vector3d left, in Vector3d right, out Vector3d result) => result = MagnitudeMax(left, right);
  public static void Clamp(in Vector3d vec, in Vector3d min, in Vector3d max, out Vector3d result) => result = Clamp(vec, min, max);
  public static void Distance(in Vector3d vec1, in Vector3d vec2, out double result) => result = Distance(vec1, vec2);
  public static void DistanceSquared(in Vector3d vec1, in Vector3d vec2, out double result) => result = DistanceSquared(vec1, vec2);
  public static void NormalizeFast(in Vector3d vec, out Vector3d result) => result = vec.Normalized();
  public static void Lerp(in Vector3d a, in Vector3d b, double blend, out Vector3d result) => result = Lerp(a, b, blend);
  public static void BaryCentric(in Vector3d a, in Vector3d b, in Vector3d c, double u, double v, out Vector3d result) =>
    result = BaryCentric(a, b, c, u, v);
  public static void TransformNormal(in Vector3d norm, in Matrix4d mat, out Vector3d result) => result = TransformNormal(norm, mat);
  public static void TransformNormalInverse(in Vector3d norm, in Matrix4d invMat, out Vector3d result) => result = TransformNormalInverse(norm, invMat);
  public static void Transform(in Vector3d vec, in Quaterniond quat, out Vector3d result) => result = Transform(vec, quat);
  public static void TransformPerspective(in Vector3d vec, in Matrix4d mat, out Vector3d result) => result = TransformPerspective(vec, mat);
  public static void CalculateAngle(in Vector3d first, in Vector3d second, out double result) => result = CalculateAngle(first, second);
}
