// Written by RefFormTests.Write_the_ref_forms_when_asked (GRCIS_WRITE_REF_FORMS=1); do not edit.
namespace OpenTK.Mathematics;

public partial struct Quaterniond
{
  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Add(in Quaterniond, in Quaterniond, out Quaterniond)"/>, for F# callers.</summary>
  public static void Add(ref Quaterniond left, ref Quaterniond right, out Quaterniond result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Add(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Conjugate(in Quaterniond, out Quaterniond)"/>, for F# callers.</summary>
  public static void Conjugate(ref Quaterniond q, out Quaterniond result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Conjugate(in q, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="FromEulerAngles(in Vector3d, out Quaterniond)"/>, for F# callers.</summary>
  public static void FromEulerAngles(ref Vector3d eulerAngles, out Quaterniond result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    FromEulerAngles(in eulerAngles, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="FromMatrix(in Matrix3d, out Quaterniond)"/>, for F# callers.</summary>
  public static void FromMatrix(ref Matrix3d matrix, out Quaterniond result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    FromMatrix(in matrix, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Invert(in Quaterniond, out Quaterniond)"/>, for F# callers.</summary>
  public static void Invert(ref Quaterniond q, out Quaterniond result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Invert(in q, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Multiply(in Quaterniond, double, out Quaterniond)"/>, for F# callers.</summary>
  public static void Multiply(ref Quaterniond quaternion, double scale, out Quaterniond result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Multiply(in quaternion, scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Multiply(in Quaterniond, in Quaterniond, out Quaterniond)"/>, for F# callers.</summary>
  public static void Multiply(ref Quaterniond left, ref Quaterniond right, out Quaterniond result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Multiply(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Normalize(in Quaterniond, out Quaterniond)"/>, for F# callers.</summary>
  public static void Normalize(ref Quaterniond q, out Quaterniond result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Normalize(in q, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Sub(in Quaterniond, in Quaterniond, out Quaterniond)"/>, for F# callers.</summary>
  public static void Sub(ref Quaterniond left, ref Quaterniond right, out Quaterniond result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Sub(in left, in right, out result);
}
