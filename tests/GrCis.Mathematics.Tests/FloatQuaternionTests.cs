using System;
using OpenTK.Mathematics;

namespace GrCis.Mathematics.Tests;

/// <summary>Values of the float Quaternion's OpenTK 3 members and the float vectors' and Matrix4's quaternion members.</summary>
public class FloatQuaternionTests
{
  /// <summary>The same rotation and length: q and −q rotate alike, so the 4D dot product is ± the squared length.</summary>
  static void Near(Quaternion expected, Quaternion actual, float eps = 1e-5f)
  {
    float dot = expected.X * actual.X + expected.Y * actual.Y + expected.Z * actual.Z + expected.W * actual.W;
    Assert.True(MathF.Abs(MathF.Abs(dot) - expected.LengthSquared) <= eps && MathF.Abs(expected.Length - actual.Length) <= eps, $"{expected} != {actual}");
  }

  [Theory]
  [InlineData(0, 0, 1, 90, 1, 0, 0, 0, 1, 0)]
  [InlineData(1, 0, 0, 90, 0, 1, 0, 0, 0, 1)]
  [InlineData(0, 1, 0, 180, 1, 2, 3, -1, 2, -3)]
  [InlineData(1, 1, 1, 120, 1, 0, 0, 0, 1, 0)]
  public void Rotations_of_vectors_by_quaternion_and_by_its_matrix_agree(float ax, float ay, float az, float degrees, float x, float y, float z, float rx, float ry, float rz)
  {
    Quaternion q = Quaternion.FromAxisAngle(new Vector3(ax, ay, az), MathHelper.DegreesToRadians(degrees));
    Vector3 v = new(x, y, z), expected = new(rx, ry, rz);
    FloatVector3Tests.Near(expected, Vector3.Transform(v, q));
    FloatVector3Tests.Near(expected, q * v);
    Vector3.Transform(ref v, ref q, out Vector3 viaRef);
    Assert.Equal(Vector3.Transform(v, q), viaRef);
    Matrix4.CreateFromQuaternion(ref q, out Matrix4 m);
    FloatVector3Tests.Near(expected, Vector3.TransformVector(v, m));
    FloatVector3Tests.Near(expected, Vector3.TransformVector(v, Matrix4.CreateFromQuaternion(2f * q)));  // any length
    Assert.Equal(v.Length, Vector3.Transform(v, q).Length, 5);
    Vector4 v4 = new(v, 7);
    Vector4.Transform(ref v4, ref q, out Vector4 r4);
    FloatVector3Tests.Near(expected, r4.Xyz);
    Assert.Equal(7, r4.W, 5);
    Assert.Equal(r4, q * v4);
    Near(q, m.ExtractRotation());
    Near(q, (Matrix4.CreateScale(2, 3, 4) * m).ExtractRotation());
  }

  [Fact]
  public void A_2d_vector_turns_in_its_plane()
  {
    Quaternion q = Quaternion.FromAxisAngle(Vector3.UnitZ, MathF.PI / 2);
    Vector2 v = new(1, 2);
    Vector2.Transform(ref v, ref q, out Vector2 r);
    Assert.True((r - new Vector2(-2, 1)).Length < 1e-5f, r.ToString());
    Assert.Equal(r, Vector2.Transform(v, q));
  }

  [Theory]
  [InlineData(0.3f, 0, 0)]
  [InlineData(0, -0.7f, 0)]
  [InlineData(0.2f, 0.5f, -1.1f)]
  public void Euler_angles_compose_x_then_y_then_z_as_OpenTK_3s_float_quaternion(float x, float y, float z)
  {
    Quaternion expected = Quaternion.FromAxisAngle(Vector3.UnitX, x) * Quaternion.FromAxisAngle(Vector3.UnitY, y) * Quaternion.FromAxisAngle(Vector3.UnitZ, z);
    Vector3 angles = new(x, y, z);
    Quaternion.FromEulerAngles(ref angles, out Quaternion viaRef);
    foreach (Quaternion q in new[] { new Quaternion(x, y, z), new Quaternion(angles), Quaternion.FromEulerAngles(x, y, z), Quaternion.FromEulerAngles(angles), viaRef })
      Near(expected, q);
  }

  [Fact]
  public void Axis_angle_round_trip_inverse_and_conjugate()
  {
    Quaternion q = Quaternion.FromAxisAngle(new Vector3(1, 2, 2), 1.2f);
    q.ToAxisAngle(out Vector3 axis, out float angle);
    FloatVector3Tests.Near(new Vector3(1, 2, 2) / 3, axis);
    Assert.Equal(1.2f, angle, 5);
    Assert.Equal(new Vector4(axis, angle), q.ToAxisAngle());
    Assert.Equal(Vector3.UnitX, Quaternion.Identity.ToAxisAngle().Xyz);
    Near(Quaternion.Identity, q * q.Inverted());
    Quaternion s = 2f * q;
    Quaternion.Invert(ref s, out Quaternion inv);
    Near(Quaternion.Identity, Quaternion.Multiply(s, inv));
    Quaternion.Conjugate(ref q, out Quaternion conj);
    Near(q.Inverted(), conj);  // unit length: the conjugate is the inverse
    Quaternion c = q;
    c.Conjugate();
    Assert.Equal(Quaternion.Conjugate(q), c);
    Quaternion.Normalize(ref s, out Quaternion n);
    Assert.Equal(1, n.Length, 5);
    Assert.Equal(1, Quaternion.Normalize(s).Length, 5);
    Assert.Equal(Quaternion.Identity, Quaternion.FromAxisAngle(Vector3.Zero, 1));
  }

  [Fact]
  public void Arithmetic_ref_twins_and_double_conversion()
  {
    Quaternion a = new(1, 2, 3, 4), b = new(-1, 0.5f, 2, 1);
    Quaternion.Add(ref a, ref b, out Quaternion sum);
    Quaternion.Sub(ref a, ref b, out Quaternion diff);
    Quaternion.Multiply(ref a, ref b, out Quaternion prod);
    Quaternion.Multiply(ref a, 2f, out Quaternion twice);
    Assert.Equal(new Quaternion(0, 2.5f, 5, 5), sum);
    Assert.Equal(Quaternion.Sub(a, b), diff);
    Assert.Equal(new Quaternion(4, 2.5f, 5, 4), a - Quaternion.Add(b, new Quaternion(-2, -1, -4, -1)));
    Quaterniond product = (Quaterniond)a * b;
    Assert.Equal((Quaternion)product, prod);
    Assert.Equal(Quaternion.Multiply(a, b), prod);
    Assert.Equal(Quaternion.Multiply(a, 2f), twice);
    Assert.Equal(a + a, twice);
    Assert.Equal(MathF.Sqrt(30), a.Length, 5);
    Assert.Equal(new Vector3(1, 2, 3), a.Xyz);
  }

  [Theory]
  [InlineData(0f)]
  [InlineData(0.25f)]
  [InlineData(0.5f)]
  [InlineData(1f)]
  public void Slerp_turns_by_the_fraction_of_the_angle(float t)
  {
    Quaternion from = Quaternion.FromAxisAngle(Vector3.UnitY, 0.2f), to = Quaternion.FromAxisAngle(Vector3.UnitY, 1.8f);
    Near(Quaternion.FromAxisAngle(Vector3.UnitY, 0.2f + 1.6f * t), Quaternion.Slerp(from, to, t));
    Near(Quaternion.FromAxisAngle(Vector3.UnitY, 0.2f + 1.6f * t), Quaternion.Slerp(from, -1f * to, t));  // the shorter arc
    Assert.Equal(to, Quaternion.Slerp(new Quaternion(0, 0, 0, 0), to, t));
  }
}
