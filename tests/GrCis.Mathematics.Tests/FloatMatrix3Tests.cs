using System;
using OpenTK.Mathematics;

namespace GrCis.Mathematics.Tests;

/// <summary>Values of the float Matrix3's OpenTK 3 members, the Vector3 transforms by it, Matrix4(Matrix3) and Quaternion.FromMatrix.</summary>
public class FloatMatrix3Tests
{
  static void Near(Matrix3 expected, Matrix3 actual, float eps = 1e-5f)
  {
    for (int r = 0; r < 3; r++)
      for (int c = 0; c < 3; c++)
        Assert.True(MathF.Abs(expected[r, c] - actual[r, c]) <= eps, $"[{r},{c}]: {expected[r, c]} != {actual[r, c]}\n{expected}\n!=\n{actual}");
  }

  /// <summary>The same rotation: q and −q rotate alike.</summary>
  static void SameRotation(Quaterniond expected, Quaternion actual, double eps = 1e-6)
  {
    double dot = expected.X * actual.X + expected.Y * actual.Y + expected.Z * actual.Z + expected.W * actual.W;
    Assert.True(Math.Abs(Math.Abs(dot) - 1) <= eps, $"{expected} != {actual}");
  }

  static readonly Matrix3 sample = new(2, 1, 0, 0, 3, 1, 1, 0, 4);

  [Fact]
  public void Construction_elements_columns_and_indexer()
  {
    Matrix3 m = sample;
    Assert.Equal(new Matrix3(new Vector3(2, 1, 0), new Vector3(0, 3, 1), new Vector3(1, 0, 4)), m);
    Assert.Equal((2f, 1f, 0f, 0f, 3f, 1f, 1f, 0f, 4f), (m.M11, m.M12, m.M13, m.M21, m.M22, m.M23, m.M31, m.M32, m.M33));
    Assert.Equal(new Vector3(2, 0, 1), m.Column0);
    Assert.Equal(new Vector3(1, 3, 0), m.Column1);
    Assert.Equal(new Vector3(0, 1, 4), m.Column2);
    Assert.Equal(new Vector3(2, 3, 4), m.Diagonal);
    Assert.Equal(9, m.Trace);
    Assert.Equal(1, m[1, 2]);
    m[1, 2] = -5;
    m.M31 = 7;
    m.Diagonal = new Vector3(-1, -2, -3);
    Assert.Equal(new Matrix3(-1, 1, 0, 0, -2, -5, 7, 0, -3), m);
    Assert.Throws<IndexOutOfRangeException>(() => m[3, 0]);
    Assert.Throws<IndexOutOfRangeException>(() => m[0, 3]);
    Assert.Throws<IndexOutOfRangeException>(() => { Matrix3 n = m; n[-1, 0] = 1; });
    Assert.Equal(new Matrix3(1, 0, 0, 0, 1, 0, 0, 0, 1), Matrix3.Identity);
    Assert.Equal(default(Matrix3), Matrix3.Zero);
    Assert.NotEqual(Matrix3.Identity, Matrix3.Zero);
    Assert.True(sample == new Matrix3(2, 1, 0, 0, 3, 1, 1, 0, 4) && sample != Matrix3.Identity);
    Assert.True(sample.Equals((object)sample) && !sample.Equals((object)(Matrix3d)sample));
    Assert.Equal(sample.GetHashCode(), new Matrix3(sample.Row0, sample.Row1, sample.Row2).GetHashCode());
    Assert.Equal($"{sample.Row0}\n{sample.Row1}\n{sample.Row2}", sample.ToString());
  }

  [Fact]
  public void The_upper_left_of_a_Matrix4_and_back()
  {
    Matrix4 big = new(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16);
    Assert.Equal(new Matrix3(1, 2, 3, 5, 6, 7, 9, 10, 11), new Matrix3(big));
    Matrix4 fromSample = new(sample);
    Assert.Equal(new Matrix4(2, 1, 0, 0, 0, 3, 1, 0, 1, 0, 4, 0, 0, 0, 0, 1), fromSample);
    Assert.Equal(sample, new Matrix3(fromSample));
    Vector3 v = new(0.5f, -2, 3);
    Assert.Equal(v * sample, Vector3.TransformVector(v, fromSample));
    Assert.Equal(v * sample, Vector3.TransformPosition(v, fromSample));   // no translation
    Assert.Equal(new Matrix4d((Matrix3d)sample), (Matrix4d)fromSample);
  }

  [Fact]
  public void Multiplication_is_row_by_column_and_applies_the_left_matrix_first()
  {
    Matrix3 b = new(1, 0, 2, -1, 1, 0, 0, 3, 1);
    // Row i of a · b = Σk a[i,k] · row k of b.
    Assert.Equal(new Matrix3(1, 1, 4, -3, 6, 1, 1, 12, 6), sample * b);
    Assert.Equal(sample * b, Matrix3.Mult(sample, b));
    Matrix3 a = sample;
    Matrix3.Mult(ref a, ref b, out Matrix3 viaRef);
    Assert.Equal(sample * b, viaRef);
    Assert.Equal(sample, sample * Matrix3.Identity);
    Assert.Equal(sample, Matrix3.Identity * sample);
    Vector3 v = new(1, -2, 0.5f);
    Assert.Equal((v * sample) * b, v * (sample * b));
    Assert.Equal(new Matrix3(3, 1, 2, -1, 4, 1, 1, 3, 5), Matrix3.Add(sample, b));
    Matrix3.Add(ref a, ref b, out Matrix3 sum);
    Assert.Equal(Matrix3.Add(sample, b), sum);
  }

  [Fact]
  public void Products_agree_with_Matrix3d()
  {
    Matrix3 r = Matrix3.CreateFromAxisAngle(new Vector3(1, 2, -1), 0.8f) * Matrix3.CreateScale(1.5f, 0.5f, 2);
    Matrix3d rd = (Matrix3d)r;
    Near((Matrix3)(rd * (Matrix3d)sample), r * sample, 1e-4f);
    Near((Matrix3)Matrix3d.Invert(rd), r.Inverted(), 1e-6f);
    Assert.Equal((float)rd.Determinant, r.Determinant, 5);
  }

  [Fact]
  public void Determinant_transpose_and_normalisation()
  {
    // Along the first row: 2·(3·4 − 1·0) − 1·(0·4 − 1·1) + 0 = 25.
    Assert.Equal(25, sample.Determinant);
    Assert.Equal(sample.Determinant, (float)((Matrix3d)sample).Determinant);
    Assert.Equal(6, Matrix3.CreateScale(1, 2, 3).Determinant);
    Matrix3 b = new(1, 0, 2, -1, 1, 0, 0, 3, 1);
    Assert.Equal(sample.Determinant * b.Determinant, (sample * b).Determinant, 3);

    Matrix3 t = Matrix3.Transpose(sample);
    Assert.Equal(new Matrix3(sample.Column0, sample.Column1, sample.Column2), t);
    Assert.Equal(t, sample.Transposed());
    Matrix3 m = sample;
    Matrix3.Transpose(ref m, out Matrix3 viaRef);
    Assert.Equal(t, viaRef);
    m.Transpose();
    Assert.Equal(t, m);
    Assert.Equal(sample, Matrix3.Transpose(t));
    Assert.Equal(sample.Determinant, t.Determinant);

    // OpenTK's "normalisation": every element divided by the determinant.
    Assert.Equal(new Matrix3(sample.Row0 / 25, sample.Row1 / 25, sample.Row2 / 25), sample.Normalized());
    m = sample;
    m.Normalize();
    Assert.Equal(sample.Normalized(), m);
  }

  [Fact]
  public void Inverse_times_matrix_is_identity_and_a_singular_matrix_is_Inverted_unchanged()
  {
    Matrix3 inv = Matrix3.Invert(sample);
    Near(Matrix3.Identity, inv * sample);
    Near(Matrix3.Identity, sample * inv);
    // The adjugate over the determinant: first row (12, −4, 1) / 25.
    Near(new Matrix3(new Vector3(12, -4, 1) / 25, new Vector3(1, 8, -2) / 25, new Vector3(-3, 1, 6) / 25), inv, 1e-6f);
    Assert.Equal(inv, sample.Inverted());
    Matrix3 m = sample;
    Matrix3.Invert(ref m, out Matrix3 viaRef);
    Assert.Equal(inv, viaRef);
    m.Invert();
    Assert.Equal(inv, m);

    Matrix3 flat = new(1, 2, 3, 4, 5, 6, 5, 7, 9);   // third row = first + second
    Assert.Equal(0, flat.Determinant);
    Assert.Equal(flat, flat.Inverted());              // OpenTK 3: unchanged, no exception
    Assert.Equal(Matrix3.Zero, Matrix3.Zero.Inverted());
    Assert.Throws<InvalidOperationException>(() => Matrix3.Invert(Matrix3.Zero));
    Assert.Throws<InvalidOperationException>(() => { Matrix3 z = Matrix3.Zero; z.Invert(); });
  }

  [Fact]
  public void Rotations_are_right_handed_and_scales_scale()
  {
    float quarter = MathF.PI / 2;
    FloatVector3Tests.Near(Vector3.UnitZ, Vector3.UnitY * Matrix3.CreateRotationX(quarter));
    FloatVector3Tests.Near(Vector3.UnitX, Vector3.UnitZ * Matrix3.CreateRotationY(quarter));
    FloatVector3Tests.Near(Vector3.UnitY, Vector3.UnitX * Matrix3.CreateRotationZ(quarter));
    Assert.Equal((Matrix3)Matrix3d.CreateRotationX(0.3f), Matrix3.CreateRotationX(0.3f));
    Assert.Equal(new Matrix3(Matrix4.CreateRotationY(0.3f)), Matrix3.CreateRotationY(0.3f));
    Near(Matrix3.CreateRotationX(0.7f), Matrix3.CreateFromAxisAngle(new Vector3(2, 0, 0), 0.7f));
    Near(Matrix3.CreateRotationZ(-1.2f), Matrix3.CreateFromAxisAngle(Vector3.UnitZ, -1.2f));
    Matrix3 rot = Matrix3.CreateFromAxisAngle(new Vector3(1, 1, 1), 2 * MathF.PI / 3);   // cycles the axes
    FloatVector3Tests.Near(Vector3.UnitY, Vector3.UnitX * rot);
    Assert.Equal(1, rot.Determinant, 5);

    Assert.Equal(new Matrix3(2, 0, 0, 0, 3, 0, 0, 0, 4), Matrix3.CreateScale(2, 3, 4));
    Assert.Equal(Matrix3.CreateScale(2, 3, 4), Matrix3.CreateScale(new Vector3(2, 3, 4)));
    Assert.Equal(Matrix3.CreateScale(5, 5, 5), Matrix3.CreateScale(5));
    Assert.Equal(new Vector3(2, -6, 12), new Vector3(1, -2, 3) * Matrix3.CreateScale(2, 3, 4));
  }

  [Fact]
  public void Out_creators_match_the_value_creators()
  {
    Vector3 v = new(1, -2, 3);
    Quaternion q = Quaternion.FromAxisAngle(v, 0.4f);
    Matrix3.CreateRotationX(0.3f, out Matrix3 rx);
    Matrix3.CreateRotationY(0.3f, out Matrix3 ry);
    Matrix3.CreateRotationZ(0.3f, out Matrix3 rz);
    Matrix3.CreateFromAxisAngle(v, 0.3f, out Matrix3 ra);
    Matrix3.CreateFromQuaternion(ref q, out Matrix3 rq);
    Matrix3.CreateScale(2f, out Matrix3 s1);
    Matrix3.CreateScale(1, 2, 3, out Matrix3 s3);
    Matrix3.CreateScale(ref v, out Matrix3 sv);
    Assert.Equal((Matrix3.CreateRotationX(0.3f), Matrix3.CreateRotationY(0.3f), Matrix3.CreateRotationZ(0.3f)), (rx, ry, rz));
    Assert.Equal(Matrix3.CreateFromAxisAngle(v, 0.3f), ra);
    Assert.Equal(Matrix3.CreateFromQuaternion(q), rq);
    Assert.Equal((Matrix3.CreateScale(2f), Matrix3.CreateScale(1, 2, 3), Matrix3.CreateScale(v)), (s1, s3, sv));
  }

  [Theory]
  [InlineData(1f, -2f, 0.5f)]
  [InlineData(0.1f, 0.2f, 0.3f)]
  [InlineData(-7f, 3f, 11f)]
  public void Vector_transforms_agree_with_Matrix3d(float x, float y, float z)
  {
    Matrix3 m = Matrix3.CreateFromAxisAngle(new Vector3(1, 2, 2), 0.9f) * new Matrix3(1, 0.5f, 0, 0, 2, 0, -1, 0, 0.5f);
    Matrix3d md = m;
    Vector3 v = new(x, y, z);
    Vector3 row = (Vector3)((Vector3d)v * md);
    Vector3 column = (Vector3)((Vector3d)v * Matrix3d.Transpose(md));   // M · v = v · Mᵀ
    float eps = 1e-5f * v.Length;
    FloatVector3Tests.Near(row, v * m, eps);
    FloatVector3Tests.Near(row, Vector3.Transform(v, m), eps);
    FloatVector3Tests.Near(column, m * v, eps);
    FloatVector3Tests.Near(column, Vector3.TransformColumn(m, v), eps);
    Assert.Equal(m.Transposed() * v, v * m);

    Vector3.Transform(ref v, ref m, out Vector3 t1);
    Vector3.TransformRow(ref v, ref m, out Vector3 t2);
    Vector3.TransformColumn(ref m, ref v, out Vector3 t3);
    Assert.Equal((v * m, v * m, m * v), (t1, t2, t3));
  }

  [Fact]
  public void OpenTK_3s_mixed_up_overloads_are_kept()
  {
    Matrix3 m = new(1, 2, 3, 4, 5, 6, 7, 8, 10);
    Vector3 v = new(1, -1, 2);
    Vector3 row = new(1 - 4 + 14, 2 - 5 + 16, 3 - 6 + 20);     // v · M
    Vector3 column = new(1 - 2 + 6, 4 - 5 + 12, 7 - 8 + 20);   // M · v
    Assert.Equal(row, v * m);
    Assert.Equal(column, m * v);
    // Transform(M, v) is v · M; its ref twin is M · v.
    Assert.Equal(row, Vector3.Transform(m, v));
    Vector3.Transform(ref m, ref v, out Vector3 refTransform);
    Assert.Equal(column, refTransform);
    // TransformRow(v, M) is M · v in OpenTK 3.3.3; its ref twin is v · M.
    Assert.Equal(column, Vector3.TransformRow(v, m));
    Vector3.TransformRow(ref v, ref m, out Vector3 refRow);
    Assert.Equal(row, refRow);
  }

  [Theory]
  [InlineData(1f, 2f, 3f, 0.7f)]
  [InlineData(1f, 0f, 0f, 3.0f)]        // trace < 0: the x-dominant branch
  [InlineData(0f, 1f, 0.1f, -3.1f)]     // the y-dominant branch
  [InlineData(0.1f, -0.2f, 1f, 2.9f)]   // the z-dominant branch
  [InlineData(0f, 0f, 1f, 0f)]          // no rotation
  public void A_rotation_matrix_gives_back_its_quaternion(float ax, float ay, float az, float angle)
  {
    Vector3 axis = new(ax, ay, az);
    Quaternion q = Quaternion.FromAxisAngle(axis, angle);
    Matrix3 m = Matrix3.CreateFromQuaternion(q);
    SameRotation(q, Quaternion.FromMatrix(m));
    Quaternion.FromMatrix(ref m, out Quaternion viaRef);
    Assert.Equal(Quaternion.FromMatrix(m), viaRef);
    SameRotation(q, Quaternion.FromMatrix(Matrix3.CreateFromAxisAngle(axis, angle)));
    SameRotation(Quaterniond.FromMatrix((Matrix3d)m), Quaternion.FromMatrix(m));
    Near(m, Matrix3.CreateFromQuaternion(Quaternion.FromMatrix(m)));
    SameRotation(q, m.ExtractRotation());
    SameRotation(q, (Matrix3.CreateScale(2, 3, 4) * m).ExtractRotation());
    SameRotation(q, m.ExtractRotation(row_normalise: false));
    // The matrix and the quaternion rotate a vector alike.
    Vector3 v = new(0.3f, -1, 2);
    FloatVector3Tests.Near(Vector3.Transform(v, q), v * m);
  }

  [Fact]
  public void Decomposition_helpers_split_scale_and_rotation()
  {
    Matrix3 rot = Matrix3.CreateFromAxisAngle(new Vector3(1, 1, 0), 0.4f);
    Matrix3 m = Matrix3.CreateScale(2, 3, 4) * rot;
    FloatVector3Tests.Near(new Vector3(2, 3, 4), m.ExtractScale());
    Near(Matrix3.CreateScale(2, 3, 4), m.ClearRotation());
    Near(rot, m.ClearScale());
    Assert.Equal(1, m.ClearScale().Determinant, 5);
  }

  [Fact]
  public void Conversions_to_and_from_Matrix3d()
  {
    Matrix3d wide = sample;
    Assert.Equal(new Matrix3d(2, 1, 0, 0, 3, 1, 1, 0, 4), wide);
    Assert.Equal(sample, (Matrix3)wide);
    Assert.Equal(new Matrix3(1f / 3, 0, 0, 0, 1, 0, 0, 0, 1), (Matrix3)new Matrix3d(1.0 / 3, 0, 0, 0, 1, 0, 0, 0, 1));
  }
}
