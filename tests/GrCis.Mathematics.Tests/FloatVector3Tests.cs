using System;
using OpenTK.Mathematics;

namespace GrCis.Mathematics.Tests;

/// <summary>Values of the float Vector3's OpenTK 3 members (Compatibility/Data/opentk3-api.tsv).</summary>
public class FloatVector3Tests
{
  internal static void Near(Vector3 expected, Vector3 actual, float eps = 1e-5f) =>
    Assert.True((expected - actual).Length <= eps, $"{expected} != {actual}");

  [Theory]
  [InlineData(1, -2, 3, -4, 5, 0.5f)]
  [InlineData(0.25f, 8, -1, 2, 2, 2)]
  public void Ref_out_twins_give_the_value_forms_results(float ax, float ay, float az, float bx, float by, float bz)
  {
    Vector3 a = new(ax, ay, az), b = new(bx, by, bz), c = new(2, -1, 4);
    Vector3.Add(ref a, ref b, out Vector3 sum);
    Vector3.Subtract(ref a, ref b, out Vector3 diff);
    Vector3.Multiply(ref a, ref b, out Vector3 prod);
    Vector3.Multiply(ref a, 3f, out Vector3 thrice);
    Vector3.Divide(ref a, ref b, out Vector3 quot);
    Vector3.Divide(ref a, 4f, out Vector3 quarter);
    Vector3.Cross(ref a, ref b, out Vector3 cross);
    Vector3.Dot(ref a, ref b, out float dot);
    Vector3.Lerp(ref a, ref b, 0.25f, out Vector3 lerp);
    Vector3.BaryCentric(ref a, ref b, ref c, 0.2f, 0.3f, out Vector3 bary);
    Vector3.Distance(ref a, ref b, out float dist);
    Vector3.DistanceSquared(ref a, ref b, out float dist2);
    Assert.Equal(new Vector3(ax + bx, ay + by, az + bz), sum);
    Assert.Equal(Vector3.Subtract(a, b), diff);
    Assert.Equal(new Vector3(ax * bx, ay * by, az * bz), prod);
    Assert.Equal(Vector3.Multiply(a, 3f), thrice);
    Assert.Equal(new Vector3(ax / bx, ay / by, az / bz), quot);
    Assert.Equal(Vector3.Divide(a, 4f), quarter);
    Assert.Equal(Vector3.Cross(a, b), cross);
    Assert.Equal(ax * bx + ay * by + az * bz, dot, 5);
    Near(a + (b - a) * 0.25f, lerp);
    Near(a + 0.2f * (b - a) + 0.3f * (c - a), bary);
    Assert.Equal((a - b).Length, dist, 5);
    Assert.Equal(dist * dist, dist2, 3);
  }

  [Fact]
  public void Min_and_max_compare_lengths_and_component_forms_compare_each_coordinate()
  {
    Vector3 a = new(3, 0, 0), b = new(1, 1, 1);
    Assert.Equal(b, Vector3.Min(a, b));
    Assert.Equal(a, Vector3.Max(a, b));
    Vector3.MagnitudeMin(ref a, ref b, out Vector3 mmin);
    Vector3.MagnitudeMax(ref a, ref b, out Vector3 mmax);
    Assert.Equal((b, a), (mmin, mmax));
    Assert.Equal(new Vector3(1, 0, 0), Vector3.ComponentMin(a, b));
    Vector3.ComponentMax(ref a, ref b, out Vector3 cmax);
    Assert.Equal(new Vector3(3, 1, 1), cmax);
    Vector3 lo = Vector3.Zero, hi = new(2, 0.5f, 2);
    Vector3.Clamp(ref a, ref lo, ref hi, out Vector3 clamped);
    Assert.Equal(new Vector3(2, 0, 0), clamped);
  }

  [Theory]
  [InlineData(3, 4, 12)]
  [InlineData(-1, 0, 0)]
  [InlineData(0.5f, 0.5f, -0.5f)]
  public void Lengths_and_normalisation(float x, float y, float z)
  {
    Vector3 v = new(x, y, z);
    float length = MathF.Sqrt(x * x + y * y + z * z);
    Assert.Equal(length, v.LengthFast, 5);
    Vector3 unit = v / length;
    Near(unit, Vector3.Normalize(v));
    Near(unit, Vector3.NormalizeFast(v));
    Vector3.Normalize(ref v, out Vector3 n1);
    Vector3.NormalizeFast(ref v, out Vector3 n2);
    Near(unit, n1);
    Near(unit, n2);
    v.NormalizeFast();
    Near(unit, v);
  }

  [Theory]
  [InlineData(1, 0, 0, 0, 1, 0, 90)]
  [InlineData(1, 1, 0, 1, 0, 0, 45)]
  [InlineData(1, 2, 3, 2, 4, 6, 0)]
  [InlineData(0, 0, 2, 0, 0, -1, 180)]
  public void CalculateAngle_is_the_angle_between_in_radians(float ax, float ay, float az, float bx, float by, float bz, float degrees)
  {
    Vector3 a = new(ax, ay, az), b = new(bx, by, bz);
    Vector3.CalculateAngle(ref a, ref b, out float angle);
    Assert.Equal(MathHelper.DegreesToRadians(degrees), angle, 3);
    Assert.Equal(angle, Vector3.CalculateAngle(a, b));
  }

  [Fact]
  public void Constructors_indexer_swizzles_and_size()
  {
    Assert.Equal(new Vector3(1, 2, 0), new Vector3(new Vector2(1, 2)));
    Assert.Equal(new Vector3(1, 2, 3), new Vector3(new Vector4(1, 2, 3, 4)));
    Assert.Equal(new Vector3(1, 2, 3), new Vector3(new Vector3(1, 2, 3)));
    Vector3 v = new(1, 2, 3);
    v[1] = 7;
    Assert.Equal((1f, 7f, 3f), (v[0], v[1], v[2]));
    Assert.Throws<IndexOutOfRangeException>(() => v[3]);
    Assert.Equal(new Vector2(3, 1), v.Zx);
    v.Zyx = new Vector3(4, 5, 6);
    Assert.Equal(new Vector3(6, 5, 4), v);
    Assert.Equal(new Vector3(2, 10, 12), new Vector3(1, 2, 3) * new Vector3(2, 5, 4));
    Assert.Equal(12, Vector3.SizeInBytes);
  }

  [Fact]
  public void Perspective_transform_divides_by_w_and_project_unproject_round_trip()
  {
    Matrix4 proj = Matrix4.CreatePerspectiveFieldOfView(1.0f, 1.5f, 0.5f, 50f);
    Matrix4 view = Matrix4.LookAt(new Vector3(1, 2, 6), Vector3.Zero, Vector3.UnitY);
    Matrix4 wvp = view * proj;
    Vector3 p = new(0.3f, -0.4f, 0.2f);
    Vector4 h = new Vector4(p, 1) * wvp;
    Vector3.TransformPerspective(ref p, ref wvp, out Vector3 ndc);
    Near(new Vector3(h.X, h.Y, h.Z) / h.W, ndc);
    Near(ndc, Vector3.TransformPerspective(p, wvp));

    Vector3 window = Vector3.Project(p, 10, 20, 640, 480, 0, 1, wvp);
    Near(new Vector3(10 + 320 * (ndc.X + 1), 20 + 240 * (ndc.Y + 1), (ndc.Z + 1) / 2), window, 1e-3f);
    Near(p, Vector3.Unproject(window, 10, 20, 640, 480, 0, 1, wvp.Inverted()), 1e-3f);
  }

  [Fact]
  public void TransformNormalInverse_ref_form_matches_the_value_form()
  {
    Matrix4 inv = Matrix4.CreateScale(1, 4, 2).Inverted();
    Vector3 n = new(1, 1, 1);
    Vector3.TransformNormalInverse(ref n, ref inv, out Vector3 r);
    Assert.Equal(Vector3.TransformNormalInverse(n, inv), r);
    Near(new Vector3(1, 0.25f, 0.5f), r);
  }
}
