// Written by RefFormTests.Write_the_ref_forms_when_asked (GRCIS_WRITE_REF_FORMS=1); do not edit.
namespace OpenTK.Mathematics;

public partial struct Vector2
{
  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Abs(in Vector2, out Vector2)"/>, for F# callers.</summary>
  public static void Abs(ref Vector2 vec, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Abs(in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Add(in Vector2, in Vector2, out Vector2)"/>, for F# callers.</summary>
  public static void Add(ref Vector2 a, ref Vector2 b, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Add(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="BaryCentric(in Vector2, in Vector2, in Vector2, float, float, out Vector2)"/>, for F# callers.</summary>
  public static void BaryCentric(ref Vector2 a, ref Vector2 b, ref Vector2 c, float u, float v, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    BaryCentric(in a, in b, in c, u, v, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Clamp(in Vector2, in Vector2, in Vector2, out Vector2)"/>, for F# callers.</summary>
  public static void Clamp(ref Vector2 vec, ref Vector2 min, ref Vector2 max, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Clamp(in vec, in min, in max, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="ComponentMax(in Vector2, in Vector2, out Vector2)"/>, for F# callers.</summary>
  public static void ComponentMax(ref Vector2 a, ref Vector2 b, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    ComponentMax(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="ComponentMin(in Vector2, in Vector2, out Vector2)"/>, for F# callers.</summary>
  public static void ComponentMin(ref Vector2 a, ref Vector2 b, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    ComponentMin(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Distance(in Vector2, in Vector2, out float)"/>, for F# callers.</summary>
  public static void Distance(ref Vector2 a, ref Vector2 b, out float result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Distance(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="DistanceSquared(in Vector2, in Vector2, out float)"/>, for F# callers.</summary>
  public static void DistanceSquared(ref Vector2 a, ref Vector2 b, out float result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    DistanceSquared(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Divide(in Vector2, float, out Vector2)"/>, for F# callers.</summary>
  public static void Divide(ref Vector2 vector, float scale, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Divide(in vector, scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Divide(in Vector2, in Vector2, out Vector2)"/>, for F# callers.</summary>
  public static void Divide(ref Vector2 vector, ref Vector2 scale, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Divide(in vector, in scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Dot(in Vector2, in Vector2, out float)"/>, for F# callers.</summary>
  public static void Dot(ref Vector2 a, ref Vector2 b, out float result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Dot(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Elerp(in Vector2, in Vector2, float, out Vector2)"/>, for F# callers.</summary>
  public static void Elerp(ref Vector2 a, ref Vector2 b, float t, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Elerp(in a, in b, t, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="GreaterThan(in Vector2, in Vector2)"/>, for F# callers.</summary>
  public static Vector2b GreaterThan(ref Vector2 left, ref Vector2 right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    GreaterThan(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="GreaterThanOrEqual(in Vector2, in Vector2)"/>, for F# callers.</summary>
  public static Vector2b GreaterThanOrEqual(ref Vector2 left, ref Vector2 right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    GreaterThanOrEqual(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Lerp(in Vector2, in Vector2, float, out Vector2)"/>, for F# callers.</summary>
  public static void Lerp(ref Vector2 a, ref Vector2 b, float blend, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Lerp(in a, in b, blend, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Lerp(in Vector2, in Vector2, Vector2, out Vector2)"/>, for F# callers.</summary>
  public static void Lerp(ref Vector2 a, ref Vector2 b, Vector2 blend, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Lerp(in a, in b, blend, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="LessThan(in Vector2, in Vector2)"/>, for F# callers.</summary>
  public static Vector2b LessThan(ref Vector2 left, ref Vector2 right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    LessThan(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="LessThanOrEqual(in Vector2, in Vector2)"/>, for F# callers.</summary>
  public static Vector2b LessThanOrEqual(ref Vector2 left, ref Vector2 right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    LessThanOrEqual(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="MagnitudeMax(in Vector2, in Vector2, out Vector2)"/>, for F# callers.</summary>
  public static void MagnitudeMax(ref Vector2 left, ref Vector2 right, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    MagnitudeMax(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="MagnitudeMin(in Vector2, in Vector2, out Vector2)"/>, for F# callers.</summary>
  public static void MagnitudeMin(ref Vector2 left, ref Vector2 right, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    MagnitudeMin(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Multiply(in Vector2, float, out Vector2)"/>, for F# callers.</summary>
  public static void Multiply(ref Vector2 vector, float scale, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Multiply(in vector, scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Multiply(in Vector2, in Vector2, out Vector2)"/>, for F# callers.</summary>
  public static void Multiply(ref Vector2 vector, ref Vector2 scale, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Multiply(in vector, in scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Normalize(in Vector2, out Vector2)"/>, for F# callers.</summary>
  public static void Normalize(ref Vector2 vec, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Normalize(in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="NormalizeFast(in Vector2, out Vector2)"/>, for F# callers.</summary>
  public static void NormalizeFast(ref Vector2 vec, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    NormalizeFast(in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="PerpDot(in Vector2, in Vector2, out float)"/>, for F# callers.</summary>
  public static void PerpDot(ref Vector2 a, ref Vector2 b, out float result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    PerpDot(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Slerp(in Vector2, in Vector2, float, out Vector2)"/>, for F# callers.</summary>
  public static void Slerp(ref Vector2 a, ref Vector2 b, float t, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Slerp(in a, in b, t, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Subtract(in Vector2, in Vector2, out Vector2)"/>, for F# callers.</summary>
  public static void Subtract(ref Vector2 a, ref Vector2 b, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Subtract(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Transform(in Vector2, in Quaternion, out Vector2)"/>, for F# callers.</summary>
  public static void Transform(ref Vector2 vec, ref Quaternion quat, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Transform(in vec, in quat, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="TransformColumn(in Matrix2, in Vector2, out Vector2)"/>, for F# callers.</summary>
  public static void TransformColumn(ref Matrix2 mat, ref Vector2 vec, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    TransformColumn(in mat, in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="TransformRow(in Vector2, in Matrix2, out Vector2)"/>, for F# callers.</summary>
  public static void TransformRow(ref Vector2 vec, ref Matrix2 mat, out Vector2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    TransformRow(in vec, in mat, out result);
}
