// Written by RefFormTests.Write_the_ref_forms_when_asked (GRCIS_WRITE_REF_FORMS=1); do not edit.
namespace OpenTK.Mathematics;

public partial struct Matrix4
{
  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Add(in Matrix4, in Matrix4, out Matrix4)"/>, for F# callers.</summary>
  public static void Add(ref Matrix4 left, ref Matrix4 right, out Matrix4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Add(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="CreateFromQuaternion(in Quaternion, out Matrix4)"/>, for F# callers.</summary>
  public static void CreateFromQuaternion(ref Quaternion q, out Matrix4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    CreateFromQuaternion(in q, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="CreateScale(in Vector3, out Matrix4)"/>, for F# callers.</summary>
  public static void CreateScale(ref Vector3 scale, out Matrix4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    CreateScale(in scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="CreateTranslation(in Vector3, out Matrix4)"/>, for F# callers.</summary>
  public static void CreateTranslation(ref Vector3 vector, out Matrix4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    CreateTranslation(in vector, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Invert(in Matrix4, out Matrix4)"/>, for F# callers.</summary>
  public static void Invert(ref Matrix4 mat, out Matrix4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Invert(in mat, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Mult(in Matrix4, in Matrix4, out Matrix4)"/>, for F# callers.</summary>
  public static void Mult(ref Matrix4 left, ref Matrix4 right, out Matrix4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Mult(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Mult(in Matrix4, float, out Matrix4)"/>, for F# callers.</summary>
  public static void Mult(ref Matrix4 left, float right, out Matrix4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Mult(in left, right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Subtract(in Matrix4, in Matrix4, out Matrix4)"/>, for F# callers.</summary>
  public static void Subtract(ref Matrix4 left, ref Matrix4 right, out Matrix4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Subtract(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Swizzle(in Matrix4, int, int, int, int, out Matrix4)"/>, for F# callers.</summary>
  public static void Swizzle(ref Matrix4 mat, int rowForRow0, int rowForRow1, int rowForRow2, int rowForRow3, out Matrix4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Swizzle(in mat, rowForRow0, rowForRow1, rowForRow2, rowForRow3, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Transpose(in Matrix4, out Matrix4)"/>, for F# callers.</summary>
  public static void Transpose(ref Matrix4 mat, out Matrix4 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Transpose(in mat, out result);
}
