// Written by RefFormTests.Write_the_ref_forms_when_asked (GRCIS_WRITE_REF_FORMS=1); do not edit.
namespace OpenTK.Mathematics;

public partial struct Vector3
{
  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Abs(in Vector3, out Vector3)"/>, for F# callers.</summary>
  public static void Abs(ref Vector3 vec, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Abs(in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Add(in Vector3, in Vector3, out Vector3)"/>, for F# callers.</summary>
  public static void Add(ref Vector3 a, ref Vector3 b, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Add(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="BaryCentric(in Vector3, in Vector3, in Vector3, float, float, out Vector3)"/>, for F# callers.</summary>
  public static void BaryCentric(ref Vector3 a, ref Vector3 b, ref Vector3 c, float u, float v, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    BaryCentric(in a, in b, in c, u, v, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="CalculateAngle(in Vector3, in Vector3, out float)"/>, for F# callers.</summary>
  public static void CalculateAngle(ref Vector3 first, ref Vector3 second, out float result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    CalculateAngle(in first, in second, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Clamp(in Vector3, in Vector3, in Vector3, out Vector3)"/>, for F# callers.</summary>
  public static void Clamp(ref Vector3 vec, ref Vector3 min, ref Vector3 max, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Clamp(in vec, in min, in max, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="ComponentMax(in Vector3, in Vector3, out Vector3)"/>, for F# callers.</summary>
  public static void ComponentMax(ref Vector3 a, ref Vector3 b, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    ComponentMax(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="ComponentMin(in Vector3, in Vector3, out Vector3)"/>, for F# callers.</summary>
  public static void ComponentMin(ref Vector3 a, ref Vector3 b, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    ComponentMin(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Cross(in Vector3, in Vector3, out Vector3)"/>, for F# callers.</summary>
  public static void Cross(ref Vector3 a, ref Vector3 b, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Cross(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Distance(in Vector3, in Vector3, out float)"/>, for F# callers.</summary>
  public static void Distance(ref Vector3 a, ref Vector3 b, out float result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Distance(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="DistanceSquared(in Vector3, in Vector3, out float)"/>, for F# callers.</summary>
  public static void DistanceSquared(ref Vector3 a, ref Vector3 b, out float result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    DistanceSquared(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Divide(in Vector3, float, out Vector3)"/>, for F# callers.</summary>
  public static void Divide(ref Vector3 vector, float scale, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Divide(in vector, scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Divide(in Vector3, in Vector3, out Vector3)"/>, for F# callers.</summary>
  public static void Divide(ref Vector3 vector, ref Vector3 scale, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Divide(in vector, in scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Dot(in Vector3, in Vector3, out float)"/>, for F# callers.</summary>
  public static void Dot(ref Vector3 a, ref Vector3 b, out float result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Dot(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Elerp(in Vector3, in Vector3, float, out Vector3)"/>, for F# callers.</summary>
  public static void Elerp(ref Vector3 a, ref Vector3 b, float t, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Elerp(in a, in b, t, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="GreaterThan(in Vector3, in Vector3)"/>, for F# callers.</summary>
  public static Vector3b GreaterThan(ref Vector3 left, ref Vector3 right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    GreaterThan(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="GreaterThanOrEqual(in Vector3, in Vector3)"/>, for F# callers.</summary>
  public static Vector3b GreaterThanOrEqual(ref Vector3 left, ref Vector3 right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    GreaterThanOrEqual(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Lerp(in Vector3, in Vector3, float, out Vector3)"/>, for F# callers.</summary>
  public static void Lerp(ref Vector3 a, ref Vector3 b, float blend, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Lerp(in a, in b, blend, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Lerp(in Vector3, in Vector3, Vector3, out Vector3)"/>, for F# callers.</summary>
  public static void Lerp(ref Vector3 a, ref Vector3 b, Vector3 blend, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Lerp(in a, in b, blend, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="LessThan(in Vector3, in Vector3)"/>, for F# callers.</summary>
  public static Vector3b LessThan(ref Vector3 left, ref Vector3 right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    LessThan(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="LessThanOrEqual(in Vector3, in Vector3)"/>, for F# callers.</summary>
  public static Vector3b LessThanOrEqual(ref Vector3 left, ref Vector3 right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    LessThanOrEqual(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="MagnitudeMax(in Vector3, in Vector3, out Vector3)"/>, for F# callers.</summary>
  public static void MagnitudeMax(ref Vector3 left, ref Vector3 right, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    MagnitudeMax(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="MagnitudeMin(in Vector3, in Vector3, out Vector3)"/>, for F# callers.</summary>
  public static void MagnitudeMin(ref Vector3 left, ref Vector3 right, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    MagnitudeMin(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Multiply(in Vector3, float, out Vector3)"/>, for F# callers.</summary>
  public static void Multiply(ref Vector3 vector, float scale, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Multiply(in vector, scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Multiply(in Vector3, in Vector3, out Vector3)"/>, for F# callers.</summary>
  public static void Multiply(ref Vector3 vector, ref Vector3 scale, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Multiply(in vector, in scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Normalize(in Vector3, out Vector3)"/>, for F# callers.</summary>
  public static void Normalize(ref Vector3 vec, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Normalize(in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="NormalizeFast(in Vector3, out Vector3)"/>, for F# callers.</summary>
  public static void NormalizeFast(ref Vector3 vec, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    NormalizeFast(in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Slerp(in Vector3, in Vector3, float, out Vector3)"/>, for F# callers.</summary>
  public static void Slerp(ref Vector3 a, ref Vector3 b, float t, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Slerp(in a, in b, t, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Subtract(in Vector3, in Vector3, out Vector3)"/>, for F# callers.</summary>
  public static void Subtract(ref Vector3 a, ref Vector3 b, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Subtract(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Transform(in Matrix3, in Vector3, out Vector3)"/>, for F# callers.</summary>
  public static void Transform(ref Matrix3 mat, ref Vector3 vec, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Transform(in mat, in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Transform(in Vector3, in Matrix3, out Vector3)"/>, for F# callers.</summary>
  public static void Transform(ref Vector3 vec, ref Matrix3 mat, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Transform(in vec, in mat, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Transform(in Vector3, in Matrix4, out Vector3)"/>, for F# callers.</summary>
  public static void Transform(ref Vector3 vec, ref Matrix4 mat, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Transform(in vec, in mat, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Transform(in Vector3, in Quaternion, out Vector3)"/>, for F# callers.</summary>
  public static void Transform(ref Vector3 vec, ref Quaternion quat, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Transform(in vec, in quat, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="TransformColumn(in Matrix3, in Vector3, out Vector3)"/>, for F# callers.</summary>
  public static void TransformColumn(ref Matrix3 mat, ref Vector3 vec, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    TransformColumn(in mat, in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="TransformNormal(in Vector3, in Matrix4, out Vector3)"/>, for F# callers.</summary>
  public static void TransformNormal(ref Vector3 norm, ref Matrix4 mat, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    TransformNormal(in norm, in mat, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="TransformNormalInverse(in Vector3, in Matrix4, out Vector3)"/>, for F# callers.</summary>
  public static void TransformNormalInverse(ref Vector3 norm, ref Matrix4 invMat, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    TransformNormalInverse(in norm, in invMat, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="TransformPerspective(in Vector3, in Matrix4, out Vector3)"/>, for F# callers.</summary>
  public static void TransformPerspective(ref Vector3 vec, ref Matrix4 mat, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    TransformPerspective(in vec, in mat, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="TransformPosition(in Vector3, in Matrix4, out Vector3)"/>, for F# callers.</summary>
  public static void TransformPosition(ref Vector3 vec, ref Matrix4 mat, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    TransformPosition(in vec, in mat, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="TransformRow(in Vector3, in Matrix3, out Vector3)"/>, for F# callers.</summary>
  public static void TransformRow(ref Vector3 vec, ref Matrix3 mat, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    TransformRow(in vec, in mat, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="TransformVector(in Vector3, in Matrix4, out Vector3)"/>, for F# callers.</summary>
  public static void TransformVector(ref Vector3 vec, ref Matrix4 mat, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    TransformVector(in vec, in mat, out result);
}
