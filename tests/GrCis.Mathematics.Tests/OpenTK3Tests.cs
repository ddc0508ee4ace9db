using System;
using OpenTK.Mathematics;

namespace GrCis.Mathematics.Tests;

/// <summary>OpenTK 3 members GrCis-era code calls: the float Matrix4, Matrix3d, and the Transform functions.</summary>
public class OpenTK3Tests
{
  [Fact]
  public void Float_matrices_compose_and_transform_points_vectors_and_normals_as_row_vectors()
  {
    Matrix4 m = Matrix4.CreateScale(2f) * Matrix4.CreateTranslation(1, 2, 3);
    Assert.Equal(new Vector3(3, 4, 5), Vector3.Transform(new Vector3(1, 1, 1), m));      // a point: scaled, then moved
    Assert.Equal(new Vector3(2, 2, 2), Vector3.TransformVector(new Vector3(1, 1, 1), m)); // a direction: no translation
    Vector3 n = Vector3.TransformNormal(new Vector3(0, 1, 0), Matrix4.CreateScale(1, 4, 1));
    Assert.Equal(0.25f, n.Y, 6);                                                          // inverse transpose
    Assert.Equal(new Vector4(3, 4, 5, 1), new Vector4(1, 1, 1, 1) * m);

    Matrix4 r = Matrix4.CreateRotationZ(MathF.PI / 2);
    Vector3 x = Vector3.Transform(Vector3.UnitX, r);
    Assert.True((x - Vector3.UnitY).Length < 1e-6f, x.ToString());
    Assert.True(((Matrix4d)(m * m.Inverted()) - Matrix4d.Identity).Row3.Length < 1e-5);
    Assert.Equal(Matrix4.Identity, Matrix4.Identity.Transposed());
    Assert.Equal(Matrix4.Scale(3f), Matrix4.CreateScale(3f));
  }

  [Fact]
  public void Double_Transform_is_the_point_transform()
  {
    Matrix4d m = Matrix4d.CreateTranslation(1, 0, 0);
    Assert.Equal(new Vector3d(1, 1, 1), Vector3d.Transform(new Vector3d(0, 1, 1), m));
    Vector3d v = new(0, 1, 1);
    Vector3d.Transform(ref v, ref m, out Vector3d w);
    Assert.Equal(new Vector3d(1, 1, 1), w);
  }

  [Fact]
  public void Matrix3d_is_the_rotation_part_and_goes_back_into_a_Matrix4d()
  {
    Matrix4d full = Matrix4d.CreateRotationY(0.3) * Matrix4d.CreateTranslation(5, 6, 7);
    var rot = new Matrix3d(full);
    var back = new Matrix4d(rot);
    Assert.Equal(Vector3d.TransformVector(new Vector3d(1, 2, 3), full), Vector3d.TransformPosition(new Vector3d(1, 2, 3), back));
    Assert.Equal(new Vector3d(1, 2, 3), Vector3d.Transform(new Vector3d(1, 2, 3), rot * rot.Inverted()), new Tolerance());
    Assert.Equal(1.0, rot.Determinant, 12);
    Assert.Equal(rot.Inverted(), rot.Transposed(), new MatrixTolerance());
    Assert.Equal(new Vector3d(2, 3, 4), new Vector3d(1, 1, 1) * Matrix3d.CreateScale(2, 3, 4));
  }

  sealed class Tolerance : System.Collections.Generic.IEqualityComparer<Vector3d>
  {
    public bool Equals(Vector3d a, Vector3d b) => (a - b).Length < 1e-12;
    public int GetHashCode(Vector3d v) => 0;
  }

  sealed class MatrixTolerance : System.Collections.Generic.IEqualityComparer<Matrix3d>
  {
    public bool Equals(Matrix3d a, Matrix3d b) => (a.Row0 - b.Row0).Length + (a.Row1 - b.Row1).Length + (a.Row2 - b.Row2).Length < 1e-12;
    public int GetHashCode(Matrix3d m) => 0;
  }
}
