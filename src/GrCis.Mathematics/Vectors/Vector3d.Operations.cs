using System.Runtime.CompilerServices;

namespace OpenTK.Mathematics;

// OpenTK 3's remaining members of Vector3d: mostly the ref/out twins of the static helpers.
public partial struct Vector3d
{
  /// <summary>The size of a Vector3d in memory, in bytes.</summary>
  public static readonly int SizeInBytes = Unsafe.SizeOf<Vector3d>();

  /// <summary>(x, y, 0).</summary>
  public Vector3d(Vector2d v) { X = v.X; Y = v.Y; Z = 0; }

  /// <summary><see cref="Add(Vector3d, Vector3d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Add(in Vector3d a, in Vector3d b, out Vector3d result) => result = a + b;
  /// <summary><see cref="Subtract(Vector3d, Vector3d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Subtract(in Vector3d a, in Vector3d b, out Vector3d result) => result = a - b;
  /// <summary><see cref="Multiply(Vector3d, double)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Multiply(in Vector3d vector, double scale, out Vector3d result) => result = vector * scale;
  /// <summary><see cref="Multiply(Vector3d, Vector3d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Multiply(in Vector3d vector, in Vector3d scale, out Vector3d result) => result = vector * scale;
  /// <summary><see cref="Divide(Vector3d, double)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Divide(in Vector3d vector, double scale, out Vector3d result) => result = vector / scale;
  /// <summary><see cref="Divide(Vector3d, Vector3d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Divide(in Vector3d vector, in Vector3d scale, out Vector3d result) => result = vector / scale;
  /// <summary><see cref="ComponentMin(Vector3d, Vector3d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void ComponentMin(in Vector3d a, in Vector3d b, out Vector3d result) => result = ComponentMin(a, b);
  /// <summary><see cref="ComponentMax(Vector3d, Vector3d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void ComponentMax(in Vector3d a, in Vector3d b, out Vector3d result) => result = ComponentMax(a, b);
  /// <summary>The shorter of the two vectors (by squared length); on a tie, <paramref name="right"/>.</summary>
  public static Vector3d MagnitudeMin(Vector3d left, Vector3d right) => left.LengthSquared < right.LengthSquared ? left : right;
  /// <summary><see cref="MagnitudeMin(Vector3d, Vector3d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void MagnitudeMin(in Vector3d left, in Vector3d right, out Vector3d result) => result = MagnitudeMin(left, right);
  /// <summary>The longer of the two vectors (by squared length); on a tie, <paramref name="left"/>.</summary>
  public static Vector3d MagnitudeMax(Vector3d left, Vector3d right) => left.LengthSquared >= right.LengthSquared ? left : right;
  /// <summary><see cref="MagnitudeMax(Vector3d, Vector3d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void MagnitudeMax(in Vector3d left, in Vector3d right, out Vector3d result) => result = MagnitudeMax(left, right);
  /// <summary><see cref="Clamp(Vector3d, Vector3d, Vector3d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Clamp(in Vector3d vec, in Vector3d min, in Vector3d max, out Vector3d result) => result = Clamp(vec, min, max);
  /// <summary><see cref="Distance(Vector3d, Vector3d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Distance(in Vector3d vec1, in Vector3d vec2, out double result) => result = Distance(vec1, vec2);
  /// <summary><see cref="DistanceSquared(Vector3d, Vector3d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void DistanceSquared(in Vector3d vec1, in Vector3d vec2, out double result) => result = DistanceSquared(vec1, vec2);
  /// <summary><see cref="NormalizeFast(Vector3d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void NormalizeFast(in Vector3d vec, out Vector3d result) => result = vec.Normalized();
  /// <summary><see cref="Lerp(Vector3d, Vector3d, double)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Lerp(in Vector3d a, in Vector3d b, double blend, out Vector3d result) => result = Lerp(a, b, blend);
  /// <summary><see cref="BaryCentric(Vector3d, Vector3d, Vector3d, double, double)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void BaryCentric(in Vector3d a, in Vector3d b, in Vector3d c, double u, double v, out Vector3d result) =>
    result = BaryCentric(a, b, c, u, v);
  /// <summary><see cref="TransformNormal(Vector3d, Matrix4d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void TransformNormal(in Vector3d norm, in Matrix4d mat, out Vector3d result) => result = TransformNormal(norm, mat);
  /// <summary><see cref="TransformNormalInverse(Vector3d, Matrix4d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void TransformNormalInverse(in Vector3d norm, in Matrix4d invMat, out Vector3d result) => result = TransformNormalInverse(norm, invMat);
  /// <summary><see cref="Transform(Vector3d, Quaterniond)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Transform(in Vector3d vec, in Quaterniond quat, out Vector3d result) => result = Transform(vec, quat);
  /// <summary><see cref="TransformPerspective(Vector3d, Matrix4d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void TransformPerspective(in Vector3d vec, in Matrix4d mat, out Vector3d result) => result = TransformPerspective(vec, mat);
  /// <summary><see cref="CalculateAngle(Vector3d, Vector3d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CalculateAngle(in Vector3d first, in Vector3d second, out double result) => result = CalculateAngle(first, second);
}
