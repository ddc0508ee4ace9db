// Written by RefFormTests.Write_the_ref_forms_when_asked (GRCIS_WRITE_REF_FORMS=1); do not edit.
namespace OpenTK.Mathematics;

public partial struct Vector4
{
  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Abs(in Vector4, out Vector4)"/>, for F# callers.</summary>
  public static void Abs(ref Vector4 vec, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Abs(in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Add(in Vector4, in Vector4, out Vector4)"/>, for F# callers.</summary>
  public static void Add(ref Vector4 a, ref Vector4 b, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Add(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="BaryCentric(in Vector4, in Vector4, in Vector4, float, float, out Vector4)"/>, for F# callers.</summary>
  public static void BaryCentric(ref Vector4 a, ref Vector4 b, ref Vector4 c, float u, float v, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    BaryCentric(in a, in b, in c, u, v, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Clamp(in Vector4, in Vector4, in Vector4, out Vector4)"/>, for F# callers.</summary>
  public static void Clamp(ref Vector4 vec, ref Vector4 min, ref Vector4 max, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Clamp(in vec, in min, in max, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="ComponentMax(in Vector4, in Vector4, out Vector4)"/>, for F# callers.</summary>
  public static void ComponentMax(ref Vector4 a, ref Vector4 b, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    ComponentMax(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="ComponentMin(in Vector4, in Vector4, out Vector4)"/>, for F# callers.</summary>
  public static void ComponentMin(ref Vector4 a, ref Vector4 b, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    ComponentMin(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Divide(in Vector4, float, out Vector4)"/>, for F# callers.</summary>
  public static void Divide(ref Vector4 vector, float scale, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Divide(in vector, scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Divide(in Vector4, in Vector4, out Vector4)"/>, for F# callers.</summary>
  public static void Divide(ref Vector4 vector, ref Vector4 scale, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Divide(in vector, in scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Dot(in Vector4, in Vector4, out float)"/>, for F# callers.</summary>
  public static void Dot(ref Vector4 a, ref Vector4 b, out float result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Dot(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Elerp(in Vector4, in Vector4, float, out Vector4)"/>, for F# callers.</summary>
  public static void Elerp(ref Vector4 a, ref Vector4 b, float t, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Elerp(in a, in b, t, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="GreaterThan(in Vector4, in Vector4)"/>, for F# callers.</summary>
  public static Vector4b GreaterThan(ref Vector4 left, ref Vector4 right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    GreaterThan(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="GreaterThanOrEqual(in Vector4, in Vector4)"/>, for F# callers.</summary>
  public static Vector4b GreaterThanOrEqual(ref Vector4 left, ref Vector4 right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    GreaterThanOrEqual(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Lerp(in Vector4, in Vector4, float, out Vector4)"/>, for F# callers.</summary>
  public static void Lerp(ref Vector4 a, ref Vector4 b, float blend, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Lerp(in a, in b, blend, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Lerp(in Vector4, in Vector4, Vector4, out Vector4)"/>, for F# callers.</summary>
  public static void Lerp(ref Vector4 a, ref Vector4 b, Vector4 blend, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Lerp(in a, in b, blend, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="LessThan(in Vector4, in Vector4)"/>, for F# callers.</summary>
  public static Vector4b LessThan(ref Vector4 left, ref Vector4 right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    LessThan(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="LessThanOrEqual(in Vector4, in Vector4)"/>, for F# callers.</summary>
  public static Vector4b LessThanOrEqual(ref Vector4 left, ref Vector4 right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    LessThanOrEqual(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="MagnitudeMax(in Vector4, in Vector4, out Vector4)"/>, for F# callers.</summary>
  public static void MagnitudeMax(ref Vector4 left, ref Vector4 right, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    MagnitudeMax(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="MagnitudeMin(in Vector4, in Vector4, out Vector4)"/>, for F# callers.</summary>
  public static void MagnitudeMin(ref Vector4 left, ref Vector4 right, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    MagnitudeMin(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Max(in Vector4, in Vector4, out Vector4)"/>, for F# callers.</summary>
  public static void Max(ref Vector4 a, ref Vector4 b, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Max(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Min(in Vector4, in Vector4, out Vector4)"/>, for F# callers.</summary>
  public static void Min(ref Vector4 a, ref Vector4 b, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Min(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Multiply(in Vector4, float, out Vector4)"/>, for F# callers.</summary>
  public static void Multiply(ref Vector4 vector, float scale, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Multiply(in vector, scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Multiply(in Vector4, in Vector4, out Vector4)"/>, for F# callers.</summary>
  public static void Multiply(ref Vector4 vector, ref Vector4 scale, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Multiply(in vector, in scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Normalize(in Vector4, out Vector4)"/>, for F# callers.</summary>
  public static void Normalize(ref Vector4 vec, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Normalize(in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="NormalizeFast(in Vector4, out Vector4)"/>, for F# callers.</summary>
  public static void NormalizeFast(ref Vector4 vec, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    NormalizeFast(in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Slerp(in Vector4, in Vector4, float, out Vector4)"/>, for F# callers.</summary>
  public static void Slerp(ref Vector4 a, ref Vector4 b, float t, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Slerp(in a, in b, t, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Subtract(in Vector4, in Vector4, out Vector4)"/>, for F# callers.</summary>
  public static void Subtract(ref Vector4 a, ref Vector4 b, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Subtract(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Transform(in Matrix4, in Vector4, out Vector4)"/>, for F# callers.</summary>
  public static void Transform(ref Matrix4 mat, ref Vector4 vec, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Transform(in mat, in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Transform(in Vector4, in Matrix4, out Vector4)"/>, for F# callers.</summary>
  public static void Transform(ref Vector4 vec, ref Matrix4 mat, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Transform(in vec, in mat, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Transform(in Vector4, in Quaternion, out Vector4)"/>, for F# callers.</summary>
  public static void Transform(ref Vector4 vec, ref Quaternion quat, out Vector4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Transform(in vec, in quat, out result);
}
