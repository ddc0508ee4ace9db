// Written by RefFormTests.Write_the_ref_forms_when_asked (GRCIS_WRITE_REF_FORMS=1); do not edit.
namespace OpenTK.Mathematics;

public partial struct Matrix3
{
  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Add(in Matrix3, in Matrix3, out Matrix3)"/>, for F# callers.</summary>
  public static void Add(ref Matrix3 left, ref Matrix3 right, out Matrix3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Add(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="CreateFromQuaternion(in Quaternion, out Matrix3)"/>, for F# callers.</summary>
  public static void CreateFromQuaternion(ref Quaternion q, out Matrix3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    CreateFromQuaternion(in q, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="CreateScale(in Vector3, out Matrix3)"/>, for F# callers.</summary>
  public static void CreateScale(ref Vector3 scale, out Matrix3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    CreateScale(in scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Invert(in Matrix3, out Matrix3)"/>, for F# callers.</summary>
  public static void Invert(ref Matrix3 mat, out Matrix3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Invert(in mat, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Mult(in Matrix3, in Matrix3, out Matrix3)"/>, for F# callers.</summary>
  public static void Mult(ref Matrix3 left, ref Matrix3 right, out Matrix3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Mult(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Transpose(in Matrix3, out Matrix3)"/>, for F# callers.</summary>
  public static void Transpose(ref Matrix3 mat, out Matrix3 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Transpose(in mat, out result);
}
