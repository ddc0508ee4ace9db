using OpenTK.Mathematics;

namespace GrCis.Mathematics.Tests;

public class Matrix4dTests
{
  static void Near(Vector3d expected, Vector3d actual, double eps = 1e-12)
  {
    Assert.True((expected - actual).Length < eps, $"expected {expected}, got {actual}");
  }

  [Fact]
  public void Row_vector_convention_applies_left_matrix_first()
  {
    // Rotate (1,0,0) by 90° about Z, then translate by (10,0,0).
    Matrix4d m = Matrix4d.RotateZ(System.Math.PI / 2) * Matrix4d.CreateTranslation(10, 0, 0);
    Near(new Vector3d(10, 1, 0), Vector3d.TransformPosition(new Vector3d(1, 0, 0), m));
  }

  [Fact]
  public void Rotations_are_right_handed_counter_clockwise()
  {
    Near(new Vector3d(0, 0, 1), Vector3d.TransformVector(Vector3d.UnitY, Matrix4d.CreateRotationX(System.Math.PI / 2)));
    Near(new Vector3d(1, 0, 0), Vector3d.TransformVector(Vector3d.UnitZ, Matrix4d.CreateRotationY(System.Math.PI / 2)));
    Near(new Vector3d(0, 1, 0), Vector3d.TransformVector(Vector3d.UnitX, Matrix4d.CreateRotationZ(System.Math.PI / 2)));
  }

  [Fact]
  public void Axis_angle_rotation_matches_the_axis_rotations()
  {
    Matrix4d a = Matrix4d.CreateFromAxisAngle(Vector3d.UnitX, 0.7);
    Matrix4d b = Matrix4d.CreateRotationX(0.7);
    Vector3d v = new(0.3, -1.2, 2.5);
    Near(Vector3d.TransformVector(v, b), Vector3d.TransformVector(v, a));
  }

  [Fact]
  public void Translation_only_moves_positions_not_vectors()
  {
    Matrix4d t = Matrix4d.CreateTranslation(1, 2, 3);
    Near(new Vector3d(1, 2, 3), Vector3d.TransformPosition(Vector3d.Zero, t));
    Near(Vector3d.Zero, Vector3d.TransformVector(Vector3d.Zero, t));
  }

  [Fact]
  public void Inverse_times_matrix_is_identity_for_general_affine_matrices()
  {
    Matrix4d m = Matrix4d.Scale(1.5, 0.2, 3) * Matrix4d.RotateY(0.4) * Matrix4d.Rotate(new Vector3d(0, 1, 1), 0.1) * Matrix4d.CreateTranslation(-2, 5, 0.5);
    Matrix4d p = m * m.Inverted();
    for (int r = 0; r < 4; r++)
      for (int c = 0; c < 4; c++)
        Assert.Equal(r == c ? 1.0 : 0.0, p[r, c], 12);
  }

  [Fact]
  public void A_singular_matrix_is_Inverted_unchanged_but_Invert_throws_as_in_OpenTK_3()
  {
    Matrix4d flat = Matrix4d.Scale(1, 0, 1) * Matrix4d.CreateTranslation(1, 2, 3);
    Assert.Equal(0.0, flat.Determinant);
    Assert.Equal(flat, flat.Inverted());
    Assert.Throws<System.InvalidOperationException>(() => Matrix4d.Invert(flat));
    Assert.Throws<System.InvalidOperationException>(() => Matrix4d.Invert(ref flat, out _));
    Assert.Throws<System.InvalidOperationException>(() => flat.Invert());
    Assert.Throws<System.InvalidOperationException>(() => Vector3d.TransformNormal(Vector3d.UnitY, flat));   // OpenTK inverts with Invert
    Assert.Equal(Matrix4d.Zero, Matrix4d.Zero.Inverted());

    Matrix4 flatF = (Matrix4)flat;
    Assert.Equal(flatF, flatF.Inverted());
    Assert.Throws<System.InvalidOperationException>(() => Matrix4.Invert(flatF));

    Matrix3d flat3 = new(1, 2, 3, 4, 5, 6, 5, 7, 9);   // third row = first + second
    Assert.Equal(0.0, flat3.Determinant);
    Assert.Equal(flat3, flat3.Inverted());
    Assert.Throws<System.InvalidOperationException>(() => Matrix3d.Invert(Matrix3d.Zero));
  }

  [Fact]
  public void Diagonal_setters_write_the_main_diagonal()
  {
    Matrix3d m3 = Matrix3d.Identity;
    m3.Diagonal = new Vector3d(2, 3, 4);
    Assert.Equal(Matrix3d.CreateScale(2, 3, 4), m3);
    Matrix4d m4 = Matrix4d.CreateTranslation(1, 2, 3);
    m4.Diagonal = new Vector4d(2, 3, 4, 5);
    Assert.Equal(new Matrix4d(2, 0, 0, 0, 0, 3, 0, 0, 0, 0, 4, 0, 1, 2, 3, 5), m4);
  }

  [Fact]
  public void Determinant_of_scale_is_product_of_factors()
  {
    Assert.Equal(6.0, (Matrix4d.Scale(1, 2, 3) * Matrix4d.RotateX(0.3)).Determinant, 12);
  }

  [Fact]
  public void Normal_transform_stays_perpendicular_under_non_uniform_scale()
  {
    Matrix4d m = Matrix4d.Scale(4, 1, 1) * Matrix4d.RotateZ(0.3);
    Vector3d n = new Vector3d(1, 1, 0).Normalized();   // normal of plane x + y = 0
    Vector3d tangent = new(1, -1, 0);                   // lies in that plane
    Vector3d n2 = Vector3d.TransformNormalInverse(n, m.Inverted());
    Vector3d t2 = Vector3d.TransformVector(tangent, m);
    Assert.Equal(0.0, Vector3d.Dot(n2, t2), 12);
    Near(n2, Vector3d.TransformNormal(n, m));
  }

  [Fact]
  public void Quaternion_matrix_and_vector_rotation_agree()
  {
    Quaterniond q = Quaterniond.FromAxisAngle(new Vector3d(1, 2, 3), 1.1);
    Vector3d v = new(-0.5, 0.25, 2);
    Near(Vector3d.TransformVector(v, Matrix4d.CreateFromQuaternion(q)), Vector3d.Transform(v, q), 1e-12);
    Near(Vector3d.TransformVector(v, Matrix4d.CreateFromAxisAngle(new Vector3d(1, 2, 3), 1.1)), Vector3d.Transform(v, q), 1e-12);
  }

  [Fact]
  public void Slerp_halfway_is_half_the_angle_and_takes_the_short_arc()
  {
    Quaterniond a = Quaterniond.Identity;
    Quaterniond b = Quaterniond.FromAxisAngle(Vector3d.UnitZ, 1.0);
    Quaterniond h = Quaterniond.Slerp(a, b, 0.5);
    h.ToAxisAngle(out Vector3d axis, out double angle);
    Assert.Equal(0.5, angle, 12);
    Near(Vector3d.UnitZ, axis, 1e-12);
    // -b is the same rotation; slerp must still go the short way.
    Quaterniond h2 = Quaterniond.Slerp(a, new Quaterniond(-b.X, -b.Y, -b.Z, -b.W), 0.5);
    Near(Vector3d.Transform(Vector3d.UnitX, h), Vector3d.Transform(Vector3d.UnitX, h2), 1e-12);
  }

  [Fact]
  public void LookAt_maps_the_target_onto_the_negative_z_axis()
  {
    Matrix4d view = Matrix4d.LookAt(new Vector3d(1, 2, 3), new Vector3d(1, 2, -7), Vector3d.UnitY);
    Near(new Vector3d(0, 0, -10), Vector3d.TransformPosition(new Vector3d(1, 2, -7), view));
  }

  [Fact]
  public void Vector_normalize_mutates_and_normalized_does_not()
  {
    Vector3d v = new(3, 0, 4);
    Vector3d n = v.Normalized();
    Assert.Equal(5.0, v.Length);
    v.Normalize();
    Assert.Equal(n, v);
    Assert.Equal(1.0, v.Length, 15);
  }
}
