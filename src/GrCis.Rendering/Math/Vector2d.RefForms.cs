// Written by RefFormTests.Write_the_ref_forms_when_asked (GRCIS_WRITE_REF_FORMS=1); do not edit.
namespace OpenTK.Mathematics;

public partial struct Vector2d
{
  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Abs(in Vector2d, out Vector2d)"/>, for F# callers.</summary>
  public static void Abs(ref Vector2d vec, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Abs(in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Add(in Vector2d, in Vector2d, out Vector2d)"/>, for F# callers.</summary>
  public static void Add(ref Vector2d a, ref Vector2d b, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Add(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="BaryCentric(in Vector2d, in Vector2d, in Vector2d, double, double, out Vector2d)"/>, for F# callers.</summary>
  public static void BaryCentric(ref Vector2d a, ref Vector2d b, ref Vector2d c, double u, double v, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    BaryCentric(in a, in b, in c, u, v, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Clamp(in Vector2d, in Vector2d, in Vector2d, out Vector2d)"/>, for F# callers.</summary>
  public static void Clamp(ref Vector2d vec, ref Vector2d min, ref Vector2d max, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Clamp(in vec, in min, in max, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="ComponentMax(in Vector2d, in Vector2d, out Vector2d)"/>, for F# callers.</summary>
  public static void ComponentMax(ref Vector2d a, ref Vector2d b, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    ComponentMax(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="ComponentMin(in Vector2d, in Vector2d, out Vector2d)"/>, for F# callers.</summary>
  public static void ComponentMin(ref Vector2d a, ref Vector2d b, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    ComponentMin(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Distance(in Vector2d, in Vector2d, out double)"/>, for F# callers.</summary>
  public static void Distance(ref Vector2d a, ref Vector2d b, out double result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Distance(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="DistanceSquared(in Vector2d, in Vector2d, out double)"/>, for F# callers.</summary>
  public static void DistanceSquared(ref Vector2d a, ref Vector2d b, out double result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    DistanceSquared(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Divide(in Vector2d, double, out Vector2d)"/>, for F# callers.</summary>
  public static void Divide(ref Vector2d vector, double scale, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Divide(in vector, scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Divide(in Vector2d, in Vector2d, out Vector2d)"/>, for F# callers.</summary>
  public static void Divide(ref Vector2d vector, ref Vector2d scale, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Divide(in vector, in scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Dot(in Vector2d, in Vector2d, out double)"/>, for F# callers.</summary>
  public static void Dot(ref Vector2d left, ref Vector2d right, out double result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Dot(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Elerp(in Vector2d, in Vector2d, double, out Vector2d)"/>, for F# callers.</summary>
  public static void Elerp(ref Vector2d a, ref Vector2d b, double t, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Elerp(in a, in b, t, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="GreaterThan(in Vector2d, in Vector2d)"/>, for F# callers.</summary>
  public static Vector2b GreaterThan(ref Vector2d left, ref Vector2d right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    GreaterThan(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="GreaterThanOrEqual(in Vector2d, in Vector2d)"/>, for F# callers.</summary>
  public static Vector2b GreaterThanOrEqual(ref Vector2d left, ref Vector2d right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    GreaterThanOrEqual(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Lerp(in Vector2d, in Vector2d, double, out Vector2d)"/>, for F# callers.</summary>
  public static void Lerp(ref Vector2d a, ref Vector2d b, double blend, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Lerp(in a, in b, blend, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Lerp(in Vector2d, in Vector2d, Vector2d, out Vector2d)"/>, for F# callers.</summary>
  public static void Lerp(ref Vector2d a, ref Vector2d b, Vector2d blend, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Lerp(in a, in b, blend, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="LessThan(in Vector2d, in Vector2d)"/>, for F# callers.</summary>
  public static Vector2b LessThan(ref Vector2d left, ref Vector2d right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    LessThan(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="LessThanOrEqual(in Vector2d, in Vector2d)"/>, for F# callers.</summary>
  public static Vector2b LessThanOrEqual(ref Vector2d left, ref Vector2d right, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    LessThanOrEqual(in left, in right);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="MagnitudeMax(in Vector2d, in Vector2d, out Vector2d)"/>, for F# callers.</summary>
  public static void MagnitudeMax(ref Vector2d left, ref Vector2d right, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    MagnitudeMax(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="MagnitudeMin(in Vector2d, in Vector2d, out Vector2d)"/>, for F# callers.</summary>
  public static void MagnitudeMin(ref Vector2d left, ref Vector2d right, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    MagnitudeMin(in left, in right, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Max(in Vector2d, in Vector2d, out Vector2d)"/>, for F# callers.</summary>
  public static void Max(ref Vector2d a, ref Vector2d b, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Max(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Min(in Vector2d, in Vector2d, out Vector2d)"/>, for F# callers.</summary>
  public static void Min(ref Vector2d a, ref Vector2d b, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Min(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Multiply(in Vector2d, double, out Vector2d)"/>, for F# callers.</summary>
  public static void Multiply(ref Vector2d vector, double scale, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Multiply(in vector, scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Multiply(in Vector2d, in Vector2d, out Vector2d)"/>, for F# callers.</summary>
  public static void Multiply(ref Vector2d vector, ref Vector2d scale, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Multiply(in vector, in scale, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Normalize(in Vector2d, out Vector2d)"/>, for F# callers.</summary>
  public static void Normalize(ref Vector2d vec, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Normalize(in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="NormalizeFast(in Vector2d, out Vector2d)"/>, for F# callers.</summary>
  public static void NormalizeFast(ref Vector2d vec, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    NormalizeFast(in vec, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Slerp(in Vector2d, in Vector2d, double, out Vector2d)"/>, for F# callers.</summary>
  public static void Slerp(ref Vector2d a, ref Vector2d b, double t, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Slerp(in a, in b, t, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Subtract(in Vector2d, in Vector2d, out Vector2d)"/>, for F# callers.</summary>
  public static void Subtract(ref Vector2d a, ref Vector2d b, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Subtract(in a, in b, out result);

  /// <summary>OpenTK 3's <c>ref</c> form of <see cref="Transform(in Vector2d, in Quaterniond, out Vector2d)"/>, for F# callers.</summary>
  public static void Transform(ref Vector2d vec, ref Quaterniond quat, out Vector2d result, OpenTk3RefForm refForm = OpenTk3RefForm.Ref) =>
    Transform(in vec, in quat, out result);
}
