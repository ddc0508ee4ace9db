// Written by RefFormTests.Write_the_ref_forms_when_asked (GRCIS_WRITE_REF_FORMS=1); do not edit.
namespace OpenTK.Mathematics;

public partial struct Quaternion
{
  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Add(in Quaternion, in Quaternion, out Quaternion)"/>, for F# callers.</summary>
  public static void Add(ref Quaternion left, ref Quaternion right, out Quaternion result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Add(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Conjugate(in Quaternion, out Quaternion)"/>, for F# callers.</summary>
  public static void Conjugate(ref Quaternion q, out Quaternion result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Conjugate(in q, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="FromEulerAngles(in Vector3, out Quaternion)"/>, for F# callers.</summary>
  public static void FromEulerAngles(ref Vector3 eulerAngles, out Quaternion result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    FromEulerAngles(in eulerAngles, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="FromMatrix(in Matrix3, out Quaternion)"/>, for F# callers.</summary>
  public static void FromMatrix(ref Matrix3 matrix, out Quaternion result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    FromMatrix(in matrix, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Invert(in Quaternion, out Quaternion)"/>, for F# callers.</summary>
  public static void Invert(ref Quaternion q, out Quaternion result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Invert(in q, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Multiply(in Quaternion, in Quaternion, out Quaternion)"/>, for F# callers.</summary>
  public static void Multiply(ref Quaternion left, ref Quaternion right, out Quaternion result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Multiply(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Multiply(in Quaternion, float, out Quaternion)"/>, for F# callers.</summary>
  public static void Multiply(ref Quaternion quaternion, float scale, out Quaternion result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Multiply(in quaternion, scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Normalize(in Quaternion, out Quaternion)"/>, for F# callers.</summary>
  public static void Normalize(ref Quaternion q, out Quaternion result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Normalize(in q, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Sub(in Quaternion, in Quaternion, out Quaternion)"/>, for F# callers.</summary>
  public static void Sub(ref Quaternion left, ref Quaternion right, out Quaternion result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Sub(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="ToEulerAngles(in Quaternion, out Vector3)"/>, for F# callers.</summary>
  public static void ToEulerAngles(ref Quaternion q, out Vector3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    ToEulerAngles(in q, out result);
}
