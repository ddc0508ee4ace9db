// Written by RefFormTests.Write_the_ref_forms_when_asked (GRCIS_WRITE_REF_FORMS=1); do not edit.
namespace OpenTK.Mathematics;

public partial struct Matrix2
{
  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Add(in Matrix2, in Matrix2, out Matrix2)"/>, for F# callers.</summary>
  public static void Add(ref Matrix2 left, ref Matrix2 right, out Matrix2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Add(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Invert(in Matrix2, out Matrix2)"/>, for F# callers.</summary>
  public static void Invert(ref Matrix2 mat, out Matrix2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Invert(in mat, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Mult(in Matrix2, in Matrix2, out Matrix2)"/>, for F# callers.</summary>
  public static void Mult(ref Matrix2 left, ref Matrix2 right, out Matrix2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Mult(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Mult(in Matrix2, float, out Matrix2)"/>, for F# callers.</summary>
  public static void Mult(ref Matrix2 left, float right, out Matrix2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Mult(in left, right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Subtract(in Matrix2, in Matrix2, out Matrix2)"/>, for F# callers.</summary>
  public static void Subtract(ref Matrix2 left, ref Matrix2 right, out Matrix2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Subtract(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Swizzle(in Matrix2, int, int, out Matrix2)"/>, for F# callers.</summary>
  public static void Swizzle(ref Matrix2 mat, int rowForRow0, int rowForRow1, out Matrix2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Swizzle(in mat, rowForRow0, rowForRow1, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Transpose(in Matrix2, out Matrix2)"/>, for F# callers.</summary>
  public static void Transpose(ref Matrix2 mat, out Matrix2 result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Transpose(in mat, out result);
}
