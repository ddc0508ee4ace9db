// Written by RefFormTests.Write_the_ref_forms_when_asked (GRCIS_WRITE_REF_FORMS=1); do not edit.
namespace OpenTK.Mathematics;

public partial struct Matrix4d
{
  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Add(in Matrix4d, in Matrix4d, out Matrix4d)"/>, for F# callers.</summary>
  public static void Add(ref Matrix4d left, ref Matrix4d right, out Matrix4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Add(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="CreateFromQuaternion(in Quaterniond, out Matrix4d)"/>, for F# callers.</summary>
  public static void CreateFromQuaternion(ref Quaterniond q, out Matrix4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    CreateFromQuaternion(in q, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="CreateTranslation(in Vector3d, out Matrix4d)"/>, for F# callers.</summary>
  public static void CreateTranslation(ref Vector3d v, out Matrix4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    CreateTranslation(in v, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Invert(in Matrix4d, out Matrix4d)"/>, for F# callers.</summary>
  public static void Invert(ref Matrix4d m, out Matrix4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Invert(in m, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Mult(in Matrix4d, double, out Matrix4d)"/>, for F# callers.</summary>
  public static void Mult(ref Matrix4d left, double right, out Matrix4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Mult(in left, right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Mult(in Matrix4d, in Matrix4d, out Matrix4d)"/>, for F# callers.</summary>
  public static void Mult(ref Matrix4d a, ref Matrix4d b, out Matrix4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Mult(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Subtract(in Matrix4d, in Matrix4d, out Matrix4d)"/>, for F# callers.</summary>
  public static void Subtract(ref Matrix4d left, ref Matrix4d right, out Matrix4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Subtract(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Transpose(in Matrix4d, out Matrix4d)"/>, for F# callers.</summary>
  public static void Transpose(ref Matrix4d mat, out Matrix4d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Transpose(in mat, out result);
}
