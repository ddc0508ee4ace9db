using System;
using System.Globalization;
using OpenTK.Mathematics;

namespace GrCis.Mathematics.Tests;

/// <summary>OpenTK 4's members of the vectors, Matrix4 and Quaternion that OpenTK 3 lacked.</summary>
public class OpenTk4MembersTests
{
  [Fact]
  public void Abs_and_component_comparisons_give_per_component_results()
  {
    Assert.Equal(new Vector3(1, 2, 0), Vector3.Abs(new Vector3(-1, 2, -0f)));
    Assert.Equal(new Vector4d(1, 2, 3, 4), Vector4d.Abs(new Vector4d(-1, 2, -3, 4)));
    Vector2.Abs(new Vector2(-5, 5), out Vector2 abs);
    Assert.Equal(new Vector2(5, 5), abs);
    Vector3 a = new(1, 2, 3), b = new(3, 2, 1);
    Assert.Equal(new Vector3b(true, false, false), Vector3.LessThan(a, b));
    Assert.Equal(new Vector3b(true, true, false), Vector3.LessThanOrEqual(a, b));
    Assert.Equal(new Vector3b(false, false, true), Vector3.GreaterThan(a, b));
    Assert.Equal(new Vector3b(false, true, true), Vector3.GreaterThanOrEqual(a, b));
    Assert.True(Vector4d.GreaterThanOrEqual(Vector4d.One, Vector4d.Zero).All());
    Assert.False(Vector2.LessThan(Vector2.One, Vector2.Zero).Any());
  }

  [Fact]
  public void Lerp_by_a_vector_blends_each_component_by_its_own_weight()
  {
    Vector3 a = new(0, 10, 100), b = new(1, 20, 300);
    Assert.Equal(new Vector3(0, 15, 300), Vector3.Lerp(a, b, new Vector3(0, 0.5f, 1)));
    Vector2d.Lerp(new Vector2d(0, 0), new Vector2d(4, 8), new Vector2d(0.25, 0.75), out Vector2d r);
    Assert.Equal(new Vector2d(1, 6), r);
  }

  [Fact]
  public void Slerp_keeps_a_quarter_turn_on_the_arc_and_falls_back_to_lerp_when_parallel()
  {
    Vector3d mid = Vector3d.Slerp(Vector3d.UnitX, Vector3d.UnitY, 0.5);
    Assert.Equal(Math.Sqrt(0.5), mid.X, 12);
    Assert.Equal(Math.Sqrt(0.5), mid.Y, 12);
    Vector2 third = Vector2.Slerp(Vector2.UnitX, Vector2.UnitY, 1f / 3);
    Assert.Equal(MathF.Cos(MathF.PI / 6), third.X, 5);
    Assert.Equal(new Vector3(2, 0, 0), Vector3.Slerp(new Vector3(1, 0, 0), new Vector3(3, 0, 0), 0.5f));
    Assert.Equal(new Vector4(0.5f, 0, 0, 0), Vector4.Slerp(Vector4.Zero, Vector4.UnitX, 0.5f));
  }

  [Fact]
  public void Elerp_interpolates_geometrically()
  {
    Vector3 r = Vector3.Elerp(new Vector3(1, 2, 10), new Vector3(4, 8, 1000), 0.5f);
    Assert.Equal(2, r.X, 5);
    Assert.Equal(4, r.Y, 5);
    Assert.Equal(100, r.Z, 3);
    Vector4d.Elerp(new Vector4d(1), new Vector4d(16), 0.25, out Vector4d q);
    Assert.Equal(2, q.W, 12);
  }

  [Fact]
  public void Boolean_vectors_combine_compare_and_swizzle_by_component()
  {
    Vector3b v = new(true, false, true);
    Assert.Equal(new Vector3b(false, true, false), !v);
    Assert.Equal(Vector3b.Not(v), v.Not());
    Assert.Equal(new Vector3b(true, false, false), Vector3b.And(v, Vector3b.UnitX));
    Assert.Equal(Vector3b.True, v | Vector3b.UnitY);
    Assert.Equal(new Vector3b(false, false, true), Vector3b.Xor(v, Vector3b.UnitX));
    Assert.True(v.Any() && !v.All() && Vector4b.True.All() && !Vector2b.False.Any());
    Assert.Equal(new Vector2b(true, false), v.Zy);
    v.Yx = new Vector2b(true, false);
    Assert.Equal(new Vector3b(false, true, true), v);
    Assert.Equal(new Vector4b(true, false, true, false), new Vector4b(new Vector3b(true, false, true)));
    Assert.Equal(new Vector3(1, 0, 1), (Vector3)new Vector3b(true, false, true));
    Vector4b w = Vector4b.UnitW;
    w[0] = true;
    Assert.Equal((true, false, false, true), (w[0], w[1], w[2], w[3]));
    Assert.Throws<IndexOutOfRangeException>(() => w[4]);
    Vector2b t = (true, false);
    var (x, y) = t;
    Assert.True(x && !y);
    Assert.False(t.Equals(Matrix2.Identity));
    Assert.Equal("(True, False)", t.ToString(CultureInfo.InvariantCulture));
  }

  [Fact]
  public void Matrix2_multiplies_inverts_and_transforms_row_and_column_vectors()
  {
    Matrix2 m = new(1, 2, 3, 4);
    Assert.Equal(-2, m.Determinant);
    Assert.Equal(5, m.Trace);
    Assert.Equal(new Matrix2(7, 10, 15, 22), m * m);
    Assert.Equal(Matrix2.Identity, m * m.Inverted());
    Assert.Equal(new Matrix2(1, 3, 2, 4), m.Transposed());
    Assert.Equal(new Matrix2(3, 4, 1, 2), Matrix2.CreateSwizzle(1, 0) * m);
    Assert.Equal(new Matrix2(3, 4, 1, 2), m.Swizzled(1, 0));
    Assert.Throws<InvalidOperationException>(() => Matrix2.Invert(new Matrix2(1, 2, 2, 4)));
    Vector2 v = new(1, 1);
    Assert.Equal(new Vector2(4, 6), v * m);
    Assert.Equal(new Vector2(3, 7), m * v);
    Vector2.TransformRow(in v, in m, out Vector2 row);
    Vector2.TransformColumn(in m, in v, out Vector2 column);
    Assert.Equal((v * m, m * v), (row, column));
    Vector2 turned = Vector2.UnitX * Matrix2.CreateRotation(MathF.PI / 2);
    Assert.Equal(0, turned.X, 6);
    Assert.Equal(1, turned.Y, 6);
    Assert.Equal(6, m[1, 0] + m[0, 1] + 1);
  }

  [Fact]
  public void Quaternion_times_Vector2_rotates_in_the_plane()
  {
    Quaternion q = Quaternion.FromAxisAngle(Vector3.UnitZ, MathF.PI / 2);
    Vector2 r = q * Vector2.UnitX;
    Assert.Equal(0, r.X, 6);
    Assert.Equal(1, r.Y, 6);
    Vector2d rd = Quaterniond.FromAxisAngle(Vector3d.UnitZ, Math.PI) * Vector2d.UnitX;
    Assert.Equal(-1, rd.X, 12);
  }

  [Theory]
  [InlineData(0.3f, -0.7f, 1.1f)]
  [InlineData(-1.2f, 0.4f, -2.9f)]
  [InlineData(0f, 0f, 0f)]
  public void ToEulerAngles_inverts_FromEulerAngles_away_from_gimbal_lock(float x, float y, float z)
  {
    Quaternion q = Quaternion.FromEulerAngles(new Vector3(x, y, z));
    Vector3 angles = q.ToEulerAngles();
    Assert.Equal(x, angles.X, 4);
    Assert.Equal(y, angles.Y, 4);
    Assert.Equal(z, angles.Z, 4);
    Quaternion.ToEulerAngles(in q, out Vector3 again);
    Assert.Equal(angles, again);
  }

  [Fact]
  public void ToEulerAngles_at_gimbal_lock_gives_a_quarter_turn_about_y_and_no_x()
  {
    Quaternion q = Quaternion.FromEulerAngles(0, MathF.PI / 2, 0.5f);
    Vector3 angles = q.ToEulerAngles();
    Assert.Equal(0, angles.X);
    Assert.Equal(MathHelper.PiOver2, angles.Y);
    Quaternion back = Quaternion.FromEulerAngles(angles);
    Assert.True(MathF.Abs(Vector4.Dot(new Vector4(q.Xyz, q.W), new Vector4(back.Xyz, back.W))) > 0.9999f, back.ToString());
  }

  [Fact]
  public void Projection_parameters_read_back_from_the_matrices_that_took_them()
  {
    Matrix4 p = Matrix4.CreatePerspectiveOffCenter(-2, 3, -1, 4, 0.5f, 100);
    p.ExtractPerspectiveOffCenter(out float l, out float r, out float b, out float t, out float n, out float f);
    Assert.Equal((-2f, 3f, -1f, 4f), (MathF.Round(l, 3), MathF.Round(r, 3), MathF.Round(b, 3), MathF.Round(t, 3)));
    Assert.Equal(0.5f, n, 3);
    Assert.Equal(100f, f, 1);
    Matrix4.CreatePerspectiveFieldOfView(1.2f, 1.5f, 1, 50).ExtractPerspectiveFieldOfView(out float fovy, out float aspect, out n, out f);
    Assert.Equal((1.2f, 1.5f, 1f, 50f), (MathF.Round(fovy, 4), MathF.Round(aspect, 4), MathF.Round(n, 3), MathF.Round(f, 2)));
    Matrix4.CreateOrthographicOffCenter(-2, 3, -1, 4, 0.5f, 100).ExtractOrthographicOffCenter(out l, out r, out b, out t, out n, out f);
    Assert.Equal((-2f, 3f, -1f, 4f, 0.5f, 100f), (MathF.Round(l, 3), MathF.Round(r, 3), MathF.Round(b, 3), MathF.Round(t, 3), MathF.Round(n, 3), MathF.Round(f, 2)));
    Matrix4.CreateOrthographic(6, 4, 1, 10).ExtractOrthographic(out float w, out float h, out n, out f);
    Assert.Equal((6f, 4f, 1f, 10f), (MathF.Round(w, 4), MathF.Round(h, 4), MathF.Round(n, 4), MathF.Round(f, 4)));
  }

  [Fact]
  public void Matrix4_swizzle_reorders_rows_and_CreateSwizzle_does_it_by_a_product()
  {
    Matrix4 m = new(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16);
    Matrix4 s = Matrix4.Swizzle(m, 3, 0, 0, 2);
    Assert.Equal((m.Row3, m.Row0, m.Row0, m.Row2), (s.Row0, s.Row1, s.Row2, s.Row3));
    Assert.Equal(s, Matrix4.CreateSwizzle(3, 0, 0, 2) * m);
    Assert.Equal(s, m.Swizzled(3, 0, 0, 2));
    m.Swizzle(3, 0, 0, 2);
    Assert.Equal(s, m);
    Assert.Throws<IndexOutOfRangeException>(() => Matrix4.CreateSwizzle(0, 1, 2, 4));
  }

  [Fact]
  public void MathHelper_forwards_System_Math_and_maps_ranges()
  {
    Assert.Equal(2.5f, MathHelper.Abs(-2.5f));
    Assert.Equal(3, MathHelper.Max(3, -7));
    Assert.Equal(-1, MathHelper.Sign(-0.5));
    Assert.Equal(2, MathHelper.Round(2.5, MidpointRounding.ToEven));
    Assert.Equal(3, MathHelper.Log2(8), 12);
    Assert.Equal(15f, MathHelper.MapRange(0.5f, 0f, 1f, 10f, 20f));
    // The int form divides before it scales, so it truncates to the range's ends.
    Assert.Equal(10, MathHelper.MapRange(5, 0, 10, 10, 20));
    Assert.Equal(150.0, MathHelper.MapRange(5.0, 0, 10, 100, 200));
  }
}
