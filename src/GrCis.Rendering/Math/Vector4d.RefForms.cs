// Written by RefFormTests.Write_the_ref_forms_when_asked (GRCIS_WRITE_REF_FORMS=1); do not edit.
namespace OpenTK.Mathematics;

public partial struct Vector4d
{
  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Abs(in Vector4d, out Vector4d)"/>, for F# callers.</summary>
  public static void Abs(ref Vector4d vec, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Abs(in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Add(in Vector4d, in Vector4d, out Vector4d)"/>, for F# callers.</summary>
  public static void Add(ref Vector4d a, ref Vector4d b, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Add(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="BaryCentric(in Vector4d, in Vector4d, in Vector4d, double, double, out Vector4d)"/>, for F# callers.</summary>
  public static void BaryCentric(ref Vector4d a, ref Vector4d b, ref Vector4d c, double u, double v, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    BaryCentric(in a, in b, in c, u, v, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Clamp(in Vector4d, in Vector4d, in Vector4d, out Vector4d)"/>, for F# callers.</summary>
  public static void Clamp(ref Vector4d vec, ref Vector4d min, ref Vector4d max, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Clamp(in vec, in min, in max, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="ComponentMax(in Vector4d, in Vector4d, out Vector4d)"/>, for F# callers.</summary>
  public static void ComponentMax(ref Vector4d a, ref Vector4d b, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    ComponentMax(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="ComponentMin(in Vector4d, in Vector4d, out Vector4d)"/>, for F# callers.</summary>
  public static void ComponentMin(ref Vector4d a, ref Vector4d b, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    ComponentMin(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Divide(in Vector4d, double, out Vector4d)"/>, for F# callers.</summary>
  public static void Divide(ref Vector4d vector, double scale, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Divide(in vector, scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Divide(in Vector4d, in Vector4d, out Vector4d)"/>, for F# callers.</summary>
  public static void Divide(ref Vector4d vector, ref Vector4d scale, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Divide(in vector, in scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Dot(in Vector4d, in Vector4d, out double)"/>, for F# callers.</summary>
  public static void Dot(ref Vector4d left, ref Vector4d right, out double result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Dot(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Elerp(in Vector4d, in Vector4d, double, out Vector4d)"/>, for F# callers.</summary>
  public static void Elerp(ref Vector4d a, ref Vector4d b, double t, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Elerp(in a, in b, t, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="GreaterThan(in Vector4d, in Vector4d)"/>, for F# callers.</summary>
  public static Vector4b GreaterThan(ref Vector4d left, ref Vector4d right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    GreaterThan(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="GreaterThanOrEqual(in Vector4d, in Vector4d)"/>, for F# callers.</summary>
  public static Vector4b GreaterThanOrEqual(ref Vector4d left, ref Vector4d right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    GreaterThanOrEqual(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Lerp(in Vector4d, in Vector4d, double, out Vector4d)"/>, for F# callers.</summary>
  public static void Lerp(ref Vector4d a, ref Vector4d b, double blend, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Lerp(in a, in b, blend, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Lerp(in Vector4d, in Vector4d, Vector4d, out Vector4d)"/>, for F# callers.</summary>
  public static void Lerp(ref Vector4d a, ref Vector4d b, Vector4d blend, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Lerp(in a, in b, blend, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="LessThan(in Vector4d, in Vector4d)"/>, for F# callers.</summary>
  public static Vector4b LessThan(ref Vector4d left, ref Vector4d right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    LessThan(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="LessThanOrEqual(in Vector4d, in Vector4d)"/>, for F# callers.</summary>
  public static Vector4b LessThanOrEqual(ref Vector4d left, ref Vector4d right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    LessThanOrEqual(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="MagnitudeMax(in Vector4d, in Vector4d, out Vector4d)"/>, for F# callers.</summary>
  public static void MagnitudeMax(ref Vector4d left, ref Vector4d right, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    MagnitudeMax(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="MagnitudeMin(in Vector4d, in Vector4d, out Vector4d)"/>, for F# callers.</summary>
  public static void MagnitudeMin(ref Vector4d left, ref Vector4d right, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    MagnitudeMin(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Max(in Vector4d, in Vector4d, out Vector4d)"/>, for F# callers.</summary>
  public static void Max(ref Vector4d a, ref Vector4d b, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Max(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Min(in Vector4d, in Vector4d, out Vector4d)"/>, for F# callers.</summary>
  public static void Min(ref Vector4d a, ref Vector4d b, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Min(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Multiply(in Vector4d, double, out Vector4d)"/>, for F# callers.</summary>
  public static void Multiply(ref Vector4d vector, double scale, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Multiply(in vector, scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Multiply(in Vector4d, in Vector4d, out Vector4d)"/>, for F# callers.</summary>
  public static void Multiply(ref Vector4d vector, ref Vector4d scale, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Multiply(in vector, in scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Normalize(in Vector4d, out Vector4d)"/>, for F# callers.</summary>
  public static void Normalize(ref Vector4d vec, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Normalize(in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="NormalizeFast(in Vector4d, out Vector4d)"/>, for F# callers.</summary>
  public static void NormalizeFast(ref Vector4d vec, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    NormalizeFast(in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Slerp(in Vector4d, in Vector4d, double, out Vector4d)"/>, for F# callers.</summary>
  public static void Slerp(ref Vector4d a, ref Vector4d b, double t, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Slerp(in a, in b, t, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Subtract(in Vector4d, in Vector4d, out Vector4d)"/>, for F# callers.</summary>
  public static void Subtract(ref Vector4d a, ref Vector4d b, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Subtract(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Transform(in Vector4d, in Matrix4d, out Vector4d)"/>, for F# callers.</summary>
  public static void Transform(ref Vector4d v, ref Matrix4d m, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Transform(in v, in m, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Transform(in Vector4d, in Quaterniond, out Vector4d)"/>, for F# callers.</summary>
  public static void Transform(ref Vector4d vec, ref Quaterniond quat, out Vector4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Transform(in vec, in quat, out result);
}
