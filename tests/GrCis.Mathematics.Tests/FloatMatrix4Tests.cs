using System;
using OpenTK.Mathematics;

namespace GrCis.Mathematics.Tests;

/// <summary>Values of the float Matrix4's OpenTK 3 members (Compatibility/Data/opentk3-api.tsv).</summary>
public class FloatMatrix4Tests
{
  static void Near(Matrix4 expected, Matrix4 actual, float eps = 1e-5f)
  {
    for (int r = 0; r < 4; r++)
      for (int c = 0; c < 4; c++)
        Assert.True(MathF.Abs(expected[r, c] - actual[r, c]) <= eps, $"[{r},{c}]: {expected[r, c]} != {actual[r, c]}");
  }

  static readonly Matrix4 sample = new(2, 1, 0, 0.5f, 0, 3, 1, 0, 1, 0, 4, 0, 5, 6, 7, 1);

  [Fact]
  public void Columns_diagonal_trace_determinant_and_indexer()
  {
    Matrix4 m = sample;
    Assert.Equal(new Vector4(2, 0, 1, 5), m.Column0);
    Assert.Equal(new Vector4(0.5f, 0, 0, 1), m.Column3);
    Assert.Equal(new Vector4(2, 3, 4, 1), m.Diagonal);
    Assert.Equal(10, m.Trace);
    Assert.Equal((float)((Matrix4d)m).Determinant, m.Determinant);
    // Along the last column (0.5 and 1): −0.5·det[rows 1–3, cols 0–2] + 1·det[rows 0–2, cols 0–2] = −0.5·45 + 25.
    Assert.Equal(2.5f, m.Determinant, 4);
    Assert.Equal(7, m[3, 2]);
    m[1, 3] = -2;
    m.Column2 = new Vector4(9, 8, 7, 6);
    m.Diagonal = Vector4.One;
    Assert.Equal(new Vector4(0, 1, 8, -2), m.Row1);
    Assert.Equal(new Vector4(9, 8, 1, 6), m.Column2);
    Assert.Throws<IndexOutOfRangeException>(() => m[4, 0]);
    Assert.Throws<IndexOutOfRangeException>(() => m[0, 4]);
  }

  [Fact]
  public void Inverse_times_matrix_is_identity_and_ref_forms_match()
  {
    Matrix4 m = sample;
    Matrix4.Invert(ref m, out Matrix4 inv);
    Assert.Equal(Matrix4.Invert(m), inv);
    Near(Matrix4.Identity, inv * m);
    Matrix4.Mult(ref inv, ref m, out Matrix4 product);
    Assert.Equal(inv * m, product);
    Matrix4.Transpose(ref m, out Matrix4 t);
    Assert.Equal(m.Column1, t.Row1);
    Matrix4.Add(ref m, ref m, out Matrix4 twice);
    Matrix4.Mult(ref m, 2f, out Matrix4 doubled);
    Assert.Equal(twice, doubled);
    Assert.Equal(Matrix4.Mult(m, 2f), Matrix4.Add(m, m));
    Matrix4.Subtract(ref twice, ref m, out Matrix4 once);
    Assert.Equal(m, once);
    Assert.Equal(Matrix4.Zero, Matrix4.Subtract(m, m));
    Assert.Equal(1, m.Normalized().Determinant * MathF.Pow(m.Determinant, 3), 3);
  }

  [Fact]
  public void Out_creators_match_the_value_creators()
  {
    Vector3 v = new(1, -2, 3);
    Matrix4.CreateRotationX(0.3f, out Matrix4 rx);
    Matrix4.CreateRotationY(0.3f, out Matrix4 ry);
    Matrix4.CreateRotationZ(0.3f, out Matrix4 rz);
    Matrix4.CreateFromAxisAngle(v, 0.3f, out Matrix4 ra);
    Matrix4.CreateScale(2f, out Matrix4 s1);
    Matrix4.CreateScale(1, 2, 3, out Matrix4 s3);
    Matrix4.CreateScale(ref v, out Matrix4 sv);
    Matrix4.CreateTranslation(1, -2, 3, out Matrix4 t3);
    Matrix4.CreateTranslation(ref v, out Matrix4 tv);
    Assert.Equal((Matrix4.CreateRotationX(0.3f), Matrix4.CreateRotationY(0.3f), Matrix4.CreateRotationZ(0.3f)), (rx, ry, rz));
    Assert.Equal(Matrix4.CreateFromAxisAngle(v, 0.3f), ra);
    Assert.Equal((Matrix4.CreateScale(2f), Matrix4.CreateScale(1, 2, 3), Matrix4.CreateScale(v)), (s1, s3, sv));
    Assert.Equal(t3, tv);
    Assert.Equal(new Vector3(1, -2, 3), tv.ExtractTranslation());
  }

  [Theory]
  [InlineData(-1, 2, -0.5f, 1, 0.5f, 9)]
  [InlineData(-2, 2, -1.5f, 1.5f, 1, 100)]
  public void Projections_map_the_view_volume_corners_to_the_unit_cube(float left, float right, float bottom, float top, float near, float far)
  {
    Matrix4.CreateOrthographicOffCenter(left, right, bottom, top, near, far, out Matrix4 ortho);
    FloatVector3Tests.Near(new Vector3(-1, -1, -1), Vector3.TransformPerspective(new Vector3(left, bottom, -near), ortho));
    FloatVector3Tests.Near(new Vector3(1, 1, 1), Vector3.TransformPerspective(new Vector3(right, top, -far), ortho));
    Matrix4.CreatePerspectiveOffCenter(left, right, bottom, top, near, far, out Matrix4 persp);
    FloatVector3Tests.Near(new Vector3(-1, -1, -1), Vector3.TransformPerspective(new Vector3(left, bottom, -near), persp));
    FloatVector3Tests.Near(new Vector3(1, 1, 1), Vector3.TransformPerspective(new Vector3(right * far / near, top * far / near, -far), persp), 1e-4f);
    float w = right - left, h = top - bottom;
    Matrix4.CreateOrthographic(w, h, near, far, out Matrix4 centred);
    Assert.Equal(Matrix4.CreateOrthographicOffCenter(-w / 2, w / 2, -h / 2, h / 2, near, far), centred);
    Assert.Equal(Matrix4.CreateOrthographic(w, h, near, far), centred);
    Matrix4.CreatePerspectiveFieldOfView(1f, w / h, near, far, out Matrix4 fov);
    Assert.Equal(Matrix4.CreatePerspectiveFieldOfView(1f, w / h, near, far), fov);
    Assert.Equal(new Vector4(0, 0, -1, 0), fov.ExtractProjection());
    Assert.Equal(Vector4.Zero, fov.ClearProjection().Column3);
  }

  [Fact]
  public void Decomposition_helpers_split_scale_rotation_and_translation()
  {
    Matrix4 m = Matrix4.CreateScale(2, 3, 4) * Matrix4.CreateFromAxisAngle(new Vector3(1, 1, 0), 0.4f) * Matrix4.CreateTranslation(1, 2, 3);
    FloatVector3Tests.Near(new Vector3(2, 3, 4), m.ExtractScale());
    Near(Matrix4.CreateScale(2, 3, 4), m.ClearTranslation().ClearRotation());
    Near(Matrix4.CreateFromAxisAngle(new Vector3(1, 1, 0), 0.4f), m.ClearScale().ClearTranslation());
    Assert.Equal(Matrix4.LookAt(new Vector3(1, 2, 3), Vector3.Zero, Vector3.UnitY), Matrix4.LookAt(1, 2, 3, 0, 0, 0, 0, 1, 0));
  }
}
