using System;
using OpenTK.Mathematics;

namespace GrCis.Mathematics.Tests;

/// <summary>
/// Results that must equal OpenTK's own (its test suites compare them exactly): the vectors' Clamp order, the float
/// Matrix4 computed in float and summed left to right, and the OpenTK 4 <c>in</c> parameters that still take OpenTK 3's
/// <c>ref</c> arguments.
/// </summary>
public class OpenTkArithmeticParityTests
{
  // min > max in every component: a value below min becomes min, any other becomes max.
  [Fact]
  public void Clamp_with_min_above_max_tests_min_first_then_max_and_never_throws()
  {
    Assert.Equal(new Vector2(5, 1), Vector2.Clamp(new Vector2(3, 7), new Vector2(5), new Vector2(1)));
    Assert.Equal(new Vector2d(5, 1), Vector2d.Clamp(new Vector2d(3, 7), new Vector2d(5), new Vector2d(1)));
    Assert.Equal(new Vector3(5, 1, 5), Vector3.Clamp(new Vector3(3, 7, -1), new Vector3(5), new Vector3(1)));
    Assert.Equal(new Vector3d(5, 1, 5), Vector3d.Clamp(new Vector3d(3, 7, -1), new Vector3d(5), new Vector3d(1)));
    Assert.Equal(new Vector4(5, 1, 5, 5), Vector4.Clamp(new Vector4(3, 7, -1, 2), new Vector4(5), new Vector4(1)));
    Assert.Equal(new Vector4d(5, 1, 5, 5), Vector4d.Clamp(new Vector4d(3, 7, -1, 2), new Vector4d(5), new Vector4d(1)));
    Vector3d v = new(3, 7, -1), lo = new(5), hi = new(1);
    Vector3d.Clamp(ref v, ref lo, ref hi, out Vector3d r);
    Assert.Equal(new Vector3d(5, 1, 5), r);
  }

  [Fact]
  public void Clamp_inside_an_ordinary_box_is_unchanged_by_the_order()
  {
    Assert.Equal(new Vector3d(0, 1, 0.5), Vector3d.Clamp(new Vector3d(-2, 9, 0.5), Vector3d.Zero, Vector3d.One));
    Assert.Equal(new Vector4(0, 1, 0.5f, 1), Vector4.Clamp(new Vector4(-2, 9, 0.5f, 1), Vector4.Zero, Vector4.One));
  }

  // 1e8 + 1 rounds back to 1e8 in float, so a float sum of 1e8 + 1 − 1e8 is 0 while a double one is 1.
  static readonly Matrix4 cancelling = new(1e8f, 1, -1e8f, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
  static readonly Matrix4 ones = new(1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1);

  [Fact]
  public void Float_matrix_product_sums_in_float_left_to_right()
  {
    Matrix4 p = cancelling * ones;
    Assert.Equal(0f, p.M11);
    Matrix4 left = cancelling, right = ones;
    Matrix4.Mult(in left, in right, out Matrix4 q);
    Assert.Equal(p, q);
    // Each element is (a·e + b·f) + c·g + d·h in float, as OpenTK's suite recomputes it.
    Matrix4 a = new(1.1f, 2.3f, -0.7f, 4.9f, 0.3f, -5.5f, 2.2f, 1.7f, 9.1f, 0.01f, -3.3f, 2.5f, -1.2f, 6.6f, 0.4f, 7.7f);
    Matrix4 ab = a * a;
    for (int r = 0; r < 4; r++)
      for (int c = 0; c < 4; c++)
        Assert.Equal(a[r, 0] * a[0, c] + a[r, 1] * a[1, c] + a[r, 2] * a[2, c] + a[r, 3] * a[3, c], ab[r, c]);
  }

  [Fact]
  public void Float_vector_transforms_sum_in_float()
  {
    Vector3 v = new(1e8f, 1, -1e8f);
    Assert.Equal(0f, Vector3.TransformPosition(v, ones).X);
    Assert.Equal(0f, Vector3.TransformVector(v, ones).X);
    Assert.Equal(0f, Vector4.Transform(new Vector4(v, 0), ones).X);
    Assert.Equal(0f, (new Vector4(v, 0) * ones).X);
    Matrix4 t = Matrix4.Transpose(ones);
    Assert.Equal(0f, Vector3.TransformNormalInverse(v, t).X);
  }

  [Fact]
  public void Float_inverse_is_the_float_cofactor_over_the_float_determinant()
  {
    // Nearly singular: the float and double inverses differ in the leading digits.
    Matrix4 m = new(1, 2, 3, 4, 2, 3.0001f, 4, 5, 3, 4, 5.0002f, 6, 4, 5, 6, 7.0003f);
    Matrix4 inv = Matrix4.Invert(m);
    float m0 = m.M11, m1 = m.M12, m2 = m.M13, m3 = m.M14, m5 = m.M22, m6 = m.M23, m7 = m.M24;
    float m9 = m.M32, m10 = m.M33, m11 = m.M34, m13 = m.M42, m14 = m.M43, m15 = m.M44;
    float m4 = m.M21, m8 = m.M31, m12 = m.M41;
    float c0 = m5 * m10 * m15 - m5 * m11 * m14 - m9 * m6 * m15 + m9 * m7 * m14 + m13 * m6 * m11 - m13 * m7 * m10;
    float c4 = -m4 * m10 * m15 + m4 * m11 * m14 + m8 * m6 * m15 - m8 * m7 * m14 - m12 * m6 * m11 + m12 * m7 * m10;
    float c8 = m4 * m9 * m15 - m4 * m11 * m13 - m8 * m5 * m15 + m8 * m7 * m13 + m12 * m5 * m11 - m12 * m7 * m9;
    float c12 = -m4 * m9 * m14 + m4 * m10 * m13 + m8 * m5 * m14 - m8 * m6 * m13 - m12 * m5 * m10 + m12 * m6 * m9;
    float det = m0 * c0 + m1 * c4 + m2 * c8 + m3 * c12;
    Assert.Equal(c0 * (1f / det), inv.M11);
    Assert.Equal(c4 * (1f / det), inv.M21);
    Assert.Equal(c12 * (1f / det), inv.M41);
    Matrix4.Invert(ref m, out Matrix4 inv2);
    Assert.Equal(inv, inv2);
    Assert.Throws<InvalidOperationException>(() => Matrix4.Invert(new Matrix4(1, 2, 3, 4, 2, 4, 6, 8, 0, 0, 1, 0, 0, 0, 0, 1)));
  }

  [Fact]
  public void Float_determinant_is_summed_in_float()
  {
    Matrix4 m = new(2, 1, 0, 0.5f, 0, 3, 1, 0, 1, 0, 4, 0, 5, 6, 7, 1);
    Assert.Equal(2.5f, m.Determinant);
    Assert.Equal(0f, new Matrix4(1, 2, 3, 4, 2, 4, 6, 8, 0, 0, 1, 0, 0, 0, 0, 1).Determinant);
  }

  [Fact]
  public void In_parameters_take_ref_in_and_plain_arguments_alike()
  {
    Vector3d a = new(1, 2, 3), b = new(4, 5, 6);
#pragma warning disable CS9191 // OpenTK 3 code passes ref to what OpenTK 4 (and we) declare in.
    Vector3d.Add(ref a, ref b, out Vector3d byRef);
    Matrix4d m = Matrix4d.CreateTranslation(1, 0, 0);
    Vector3d.Transform(ref a, ref m, out Vector3d moved);
#pragma warning restore CS9191
    Vector3d.Add(in a, in b, out Vector3d byIn);
    Vector3d.Add(a, b, out Vector3d plain);
    Assert.Equal(new Vector3d(5, 7, 9), byRef);
    Assert.Equal(byRef, byIn);
    Assert.Equal(byRef, plain);
    Assert.Equal(new Vector3d(2, 2, 3), moved);
  }
}
