// Written by RefFormTests.Write_the_ref_forms_when_asked (GRCIS_WRITE_REF_FORMS=1); do not edit.
namespace OpenTK.Mathematics;

public partial struct Matrix3d
{
  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Add(in Matrix3d, in Matrix3d, out Matrix3d)"/>, for F# callers.</summary>
  public static void Add(ref Matrix3d left, ref Matrix3d right, out Matrix3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Add(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="CreateFromQuaternion(in Quaterniond, out Matrix3d)"/>, for F# callers.</summary>
  public static void CreateFromQuaternion(ref Quaterniond q, out Matrix3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    CreateFromQuaternion(in q, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="CreateScale(in Vector3d, out Matrix3d)"/>, for F# callers.</summary>
  public static void CreateScale(ref Vector3d scale, out Matrix3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    CreateScale(in scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Invert(in Matrix3d, out Matrix3d)"/>, for F# callers.</summary>
  public static void Invert(ref Matrix3d mat, out Matrix3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Invert(in mat, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Mult(in Matrix3d, in Matrix3d, out Matrix3d)"/>, for F# callers.</summary>
  public static void Mult(ref Matrix3d left, ref Matrix3d right, out Matrix3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Mult(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Transpose(in Matrix3d, out Matrix3d)"/>, for F# callers.</summary>
  public static void Transpose(ref Matrix3d mat, out Matrix3d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Transpose(in mat, out result);
}
