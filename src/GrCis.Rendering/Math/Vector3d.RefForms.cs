// Written by RefFormTests.Write_the_ref_forms_when_asked (GRCIS_WRITE_REF_FORMS=1); do not edit.
namespace OpenTK.Mathematics;

public partial struct Vector3d
{
  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Abs(in Vector3d, out Vector3d)"/>, for F# callers.</summary>
  public static void Abs(ref Vector3d vec, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Abs(in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Add(in Vector3d, in Vector3d, out Vector3d)"/>, for F# callers.</summary>
  public static void Add(ref Vector3d a, ref Vector3d b, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Add(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="BaryCentric(in Vector3d, in Vector3d, in Vector3d, double, double, out Vector3d)"/>, for F# callers.</summary>
  public static void BaryCentric(ref Vector3d a, ref Vector3d b, ref Vector3d c, double u, double v, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    BaryCentric(in a, in b, in c, u, v, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="CalculateAngle(in Vector3d, in Vector3d, out double)"/>, for F# callers.</summary>
  public static void CalculateAngle(ref Vector3d first, ref Vector3d second, out double result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    CalculateAngle(in first, in second, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Clamp(in Vector3d, in Vector3d, in Vector3d, out Vector3d)"/>, for F# callers.</summary>
  public static void Clamp(ref Vector3d vec, ref Vector3d min, ref Vector3d max, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Clamp(in vec, in min, in max, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="ComponentMax(in Vector3d, in Vector3d, out Vector3d)"/>, for F# callers.</summary>
  public static void ComponentMax(ref Vector3d a, ref Vector3d b, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    ComponentMax(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="ComponentMin(in Vector3d, in Vector3d, out Vector3d)"/>, for F# callers.</summary>
  public static void ComponentMin(ref Vector3d a, ref Vector3d b, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    ComponentMin(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Cross(in Vector3d, in Vector3d, out Vector3d)"/>, for F# callers.</summary>
  public static void Cross(ref Vector3d a, ref Vector3d b, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Cross(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Distance(in Vector3d, in Vector3d, out double)"/>, for F# callers.</summary>
  public static void Distance(ref Vector3d vec1, ref Vector3d vec2, out double result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Distance(in vec1, in vec2, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="DistanceSquared(in Vector3d, in Vector3d, out double)"/>, for F# callers.</summary>
  public static void DistanceSquared(ref Vector3d vec1, ref Vector3d vec2, out double result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    DistanceSquared(in vec1, in vec2, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Divide(in Vector3d, double, out Vector3d)"/>, for F# callers.</summary>
  public static void Divide(ref Vector3d vector, double scale, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Divide(in vector, scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Divide(in Vector3d, in Vector3d, out Vector3d)"/>, for F# callers.</summary>
  public static void Divide(ref Vector3d vector, ref Vector3d scale, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Divide(in vector, in scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Dot(in Vector3d, in Vector3d, out double)"/>, for F# callers.</summary>
  public static void Dot(ref Vector3d a, ref Vector3d b, out double result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Dot(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Elerp(in Vector3d, in Vector3d, double, out Vector3d)"/>, for F# callers.</summary>
  public static void Elerp(ref Vector3d a, ref Vector3d b, double t, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Elerp(in a, in b, t, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="GreaterThan(in Vector3d, in Vector3d)"/>, for F# callers.</summary>
  public static Vector3b GreaterThan(ref Vector3d left, ref Vector3d right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    GreaterThan(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="GreaterThanOrEqual(in Vector3d, in Vector3d)"/>, for F# callers.</summary>
  public static Vector3b GreaterThanOrEqual(ref Vector3d left, ref Vector3d right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    GreaterThanOrEqual(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Lerp(in Vector3d, in Vector3d, double, out Vector3d)"/>, for F# callers.</summary>
  public static void Lerp(ref Vector3d a, ref Vector3d b, double blend, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Lerp(in a, in b, blend, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Lerp(in Vector3d, in Vector3d, Vector3d, out Vector3d)"/>, for F# callers.</summary>
  public static void Lerp(ref Vector3d a, ref Vector3d b, Vector3d blend, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Lerp(in a, in b, blend, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="LessThan(in Vector3d, in Vector3d)"/>, for F# callers.</summary>
  public static Vector3b LessThan(ref Vector3d left, ref Vector3d right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    LessThan(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="LessThanOrEqual(in Vector3d, in Vector3d)"/>, for F# callers.</summary>
  public static Vector3b LessThanOrEqual(ref Vector3d left, ref Vector3d right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    LessThanOrEqual(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="MagnitudeMax(in Vector3d, in Vector3d, out Vector3d)"/>, for F# callers.</summary>
  public static void MagnitudeMax(ref Vector3d left, ref Vector3d right, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    MagnitudeMax(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="MagnitudeMin(in Vector3d, in Vector3d, out Vector3d)"/>, for F# callers.</summary>
  public static void MagnitudeMin(ref Vector3d left, ref Vector3d right, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    MagnitudeMin(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Multiply(in Vector3d, double, out Vector3d)"/>, for F# callers.</summary>
  public static void Multiply(ref Vector3d vector, double scale, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Multiply(in vector, scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Multiply(in Vector3d, in Vector3d, out Vector3d)"/>, for F# callers.</summary>
  public static void Multiply(ref Vector3d vector, ref Vector3d scale, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Multiply(in vector, in scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Normalize(in Vector3d, out Vector3d)"/>, for F# callers.</summary>
  public static void Normalize(ref Vector3d v, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Normalize(in v, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="NormalizeFast(in Vector3d, out Vector3d)"/>, for F# callers.</summary>
  public static void NormalizeFast(ref Vector3d vec, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    NormalizeFast(in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Slerp(in Vector3d, in Vector3d, double, out Vector3d)"/>, for F# callers.</summary>
  public static void Slerp(ref Vector3d a, ref Vector3d b, double t, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Slerp(in a, in b, t, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Subtract(in Vector3d, in Vector3d, out Vector3d)"/>, for F# callers.</summary>
  public static void Subtract(ref Vector3d a, ref Vector3d b, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Subtract(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Transform(in Vector3d, in Matrix4d, out Vector3d)"/>, for F# callers.</summary>
  public static void Transform(ref Vector3d vec, ref Matrix4d mat, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Transform(in vec, in mat, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Transform(in Vector3d, in Quaterniond, out Vector3d)"/>, for F# callers.</summary>
  public static void Transform(ref Vector3d vec, ref Quaterniond quat, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Transform(in vec, in quat, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="TransformNormal(in Vector3d, in Matrix4d, out Vector3d)"/>, for F# callers.</summary>
  public static void TransformNormal(ref Vector3d norm, ref Matrix4d mat, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    TransformNormal(in norm, in mat, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="TransformNormalInverse(in Vector3d, in Matrix4d, out Vector3d)"/>, for F# callers.</summary>
  public static void TransformNormalInverse(ref Vector3d norm, ref Matrix4d invMat, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    TransformNormalInverse(in norm, in invMat, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="TransformPerspective(in Vector3d, in Matrix4d, out Vector3d)"/>, for F# callers.</summary>
  public static void TransformPerspective(ref Vector3d vec, ref Matrix4d mat, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    TransformPerspective(in vec, in mat, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="TransformPosition(in Vector3d, in Matrix4d, out Vector3d)"/>, for F# callers.</summary>
  public static void TransformPosition(ref Vector3d v, ref Matrix4d m, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    TransformPosition(in v, in m, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="TransformVector(in Vector3d, in Matrix4d, out Vector3d)"/>, for F# callers.</summary>
  public static void TransformVector(ref Vector3d v, ref Matrix4d m, out Vector3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    TransformVector(in v, in m, out result);
}
