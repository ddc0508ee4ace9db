using System;
using System.Linq;
using OpenTK.Mathematics;

namespace GrCis.Mathematics.Tests;

/// <summary>Values of the OpenTK 3 members ported for the API list (Compatibility/Data/opentk3-api.tsv).</summary>
public class OpenTK3OperationsTests
{
  const double Eps = 1e-12;

  static void Near(Vector3d expected, Vector3d actual, double eps = Eps) => Assert.True((expected - actual).Length <= eps, $"{expected} != {actual}");

  static void Near(Matrix4d expected, Matrix4d actual, double eps = Eps)
  {
    for (int r = 0; r < 4; r++)
      for (int c = 0; c < 4; c++)
        Assert.True(System.Math.Abs(expected[r, c] - actual[r, c]) <= eps, $"[{r},{c}]: {expected[r, c]} != {actual[r, c]}");
  }

  [Fact]
  public void Ref_out_twins_give_the_value_forms_results()
  {
    Vector3d a = new(1, -2, 3), b = new(-4, 5, 0.5), c = new(2, 2, 2);
    Vector3d.Add(ref a, ref b, out Vector3d sum);
    Vector3d.Subtract(ref a, ref b, out Vector3d diff);
    Vector3d.Multiply(ref a, 2.0, out Vector3d twice);
    Vector3d.Divide(ref a, ref c, out Vector3d half);
    Vector3d.Lerp(ref a, ref b, 0.25, out Vector3d lerp);
    Vector3d.BaryCentric(ref a, ref b, ref c, 0.2, 0.3, out Vector3d bary);
    Vector3d.Distance(ref a, ref b, out double dist);
    Assert.Equal(new Vector3d(-3, 3, 3.5), sum);
    Assert.Equal(new Vector3d(5, -7, 2.5), diff);
    Assert.Equal(new Vector3d(2, -4, 6), twice);
    Assert.Equal(new Vector3d(0.5, -1, 1.5), half);
    Near(new Vector3d(1 - 1.25, -2 + 1.75, 3 - 0.625), lerp);
    Near(a + 0.2 * (b - a) + 0.3 * (c - a), bary);
    Assert.Equal(System.Math.Sqrt(25 + 49 + 6.25), dist, 12);
  }

  [Fact]
  public void Min_and_max_are_per_component_in_2d_and_4d_and_by_length_for_magnitude()
  {
    Assert.Equal(new Vector2d(1, -5), Vector2d.Min(new Vector2d(1, 2), new Vector2d(3, -5)));
    Assert.Equal(new Vector4d(3, 2, 0, 9), Vector4d.Max(new Vector4d(1, 2, 0, 9), new Vector4d(3, -5, -1, 0)));
    Assert.Equal(new Vector3d(0, 0, 1), Vector3d.MagnitudeMin(new Vector3d(0, 0, 1), new Vector3d(1, 1, 0)));
    Assert.Equal(new Vector4d(0, 2, 0, 0), Vector4d.MagnitudeMax(new Vector4d(1, 1, 0, 0), new Vector4d(0, 2, 0, 0)));
    Assert.Equal(new Vector4d(0, 1, 0.5, -1), Vector4d.Clamp(new Vector4d(-3, 7, 0.5, -2), new Vector4d(0, 0, 0, -1), new Vector4d(1, 1, 1, 1)));
    Assert.Equal(new Vector2d(1, 0), Vector2d.Clamp(new Vector2d(4, -4), Vector2d.Zero, Vector2d.One));
  }

  [Fact]
  public void Constructors_from_smaller_vectors_fill_zeros_and_conversions_round_trip()
  {
    Assert.Equal(new Vector3d(1, 2, 0), new Vector3d(new Vector2d(1, 2)));
    Assert.Equal(new Vector4d(1, 2, 3, 0), new Vector4d(new Vector3d(1, 2, 3)));
    Assert.Equal(new Vector4d(1, 2, 0, 0), new Vector4d(new Vector2d(1, 2)));
    Assert.Equal(new Vector2d(0.5, -2), (Vector2d)(Vector2)new Vector2d(0.5, -2));
    Assert.Equal(24, Vector3d.SizeInBytes);
    Assert.Equal(32, Vector4d.SizeInBytes);
  }

  [Fact]
  public void Quaternion_transforms_of_2d_and_4d_vectors_rotate_xyz_and_keep_w()
  {
    Quaterniond q = Quaterniond.FromAxisAngle(Vector3d.UnitZ, System.Math.PI / 2);
    Vector2d r2 = Vector2d.Transform(new Vector2d(1, 0), q);
    Assert.Equal(0, r2.X, 12);
    Assert.Equal(1, r2.Y, 12);
    Vector4d r4 = Vector4d.Transform(new Vector4d(0, 1, 5, 7), q);
    Near(new Vector3d(-1, 0, 5), r4.Xyz);
    Assert.Equal(7, r4.W);
  }

  [Fact]
  public void A_rotation_matrix_gives_back_its_quaternion()
  {
    foreach ((Vector3d axis, double angle) in new[] { (new Vector3d(1, 2, 3), 0.7), (Vector3d.UnitX, 3.0), (new Vector3d(0, 1, 1), -2.9), (new Vector3d(-1, 0.2, 0), 3.1) })
    {
      Quaterniond q = Quaterniond.FromAxisAngle(axis, angle);
      Quaterniond back = Quaterniond.FromMatrix(Matrix3d.CreateFromAxisAngle(axis, angle));
      double dot = System.Math.Abs(Quaterniond.Dot(q, back));  // q and −q are the same rotation
      Assert.Equal(1, dot, 10);
      Quaterniond scaled = (Matrix4d.CreateScale(2, 3, 4) * Matrix4d.CreateFromAxisAngle(axis, angle)).ExtractRotation();
      Assert.Equal(1, System.Math.Abs(Quaterniond.Dot(q, scaled)), 10);
      Near(Vector3d.Transform(new Vector3d(0.3, -1, 2), q), new Vector3d(0.3, -1, 2) * Matrix3d.CreateFromQuaternion(q), 1e-12);
    }
  }

  [Fact]
  public void Matrix_helpers_match_their_definitions()
  {
    Matrix4d m = Matrix4d.CreateScale(2, 3, 4) * Matrix4d.CreateFromAxisAngle(new Vector3d(1, 1, 0), 0.4) * Matrix4d.CreateTranslation(1, 2, 3);
    Near(Matrix4d.CreateScale(2, 3, 4), m.ClearTranslation().ClearRotation(), 1e-12);
    Matrix4d.Add(ref m, ref m, out Matrix4d twice);
    Near(m * 2.0, twice);
    Near(Matrix4d.Zero, Matrix4d.Subtract(m, m));
    Assert.Equal(1, m.Normalized().Determinant * System.Math.Pow(m.Determinant, 3), 9);
    Matrix4d p = Matrix4d.CreatePerspectiveFieldOfView(1.0, 1.5, 0.1, 100);
    Assert.Equal(new Vector4d(0, 0, -1, 0), p.ExtractProjection());
    Assert.Equal(Vector4d.Zero, p.ClearProjection().Column3);
    Near(Matrix4d.CreatePerspectiveOffCenter(-1, 2, -0.5, 1, 0.5, 9), Matrix4d.Frustum(-1, 2, -0.5, 1, 0.5, 9));
    Matrix4d.CreateRotationY(0.3, out Matrix4d ry);
    Near(Matrix4d.CreateRotationY(0.3), ry);
    Matrix4d.Transpose(ref m, out Matrix4d mt);
    Near(Matrix4d.Transpose(m), mt);
  }

  [Fact]
  public void Matrix3d_columns_indexer_and_inverse()
  {
    Matrix3d m = new(2, 1, 0, 0, 3, 1, 1, 0, 4);
    Assert.Equal(new Vector3d(2, 0, 1), m.Column0);
    Assert.Equal(new Vector3d(2, 3, 4), m.Diagonal);
    Assert.Equal(9, m.Trace);
    Assert.Equal(1, m[1, 2]);
    Matrix3d.Invert(ref m, out Matrix3d inv);
    Matrix3d id = m * inv;
    for (int r = 0; r < 3; r++)
      for (int c = 0; c < 3; c++)
        Assert.Equal(r == c ? 1 : 0, id[r, c], 12);
    Assert.Equal(new Vector3d(System.Math.Sqrt(5), System.Math.Sqrt(10), System.Math.Sqrt(17)), m.ExtractScale());
    Assert.Equal(new Matrix3d(4, 2, 0, 0, 6, 2, 2, 0, 8), Matrix3d.Add(m, m));
  }

  [Fact]
  public void MathHelper_additions()
  {
    Assert.Equal(120, MathHelper.Factorial(5));
    Assert.Equal(1, MathHelper.Factorial(0));
    Assert.Equal(10, MathHelper.BinomialCoefficient(5, 2));
    Assert.Equal(8.0, MathHelper.NextPowerOfTwo(5.5));
    Assert.Equal(4f, MathHelper.NextPowerOfTwo(4f));
    double a = 1, b = 2;
    MathHelper.Swap(ref a, ref b);
    Assert.Equal((2.0, 1.0), (a, b));
    Assert.True(MathHelper.ApproximatelyEqual(1f, MathF.BitIncrement(1f), 0));
    Assert.True(MathHelper.ApproximatelyEqual(-0f, 0f, 0));
    Assert.False(MathHelper.ApproximatelyEqual(1f, 1.001f, 4));
    // Relative: 1e6 and 1e6 + 1 differ by 5e-7 of their sum.
    Assert.True(MathHelper.ApproximatelyEqualEpsilon(1e6, 1e6 + 1, 1e-6));
    Assert.False(MathHelper.ApproximatelyEqualEpsilon(1e-3, 2e-3, 1e-6));
    Assert.True(MathHelper.ApproximatelyEquivalent(1.0, 1.05, 0.1));
    Assert.True(MathHelper.ApproximatelyEquivalent(double.PositiveInfinity, double.PositiveInfinity, 0));
  }
}

public class OpenTK3SwizzleTests
{
  static double Component(object vector, char name) => Convert.ToDouble(vector.GetType().GetField(name.ToString().ToUpperInvariant())!.GetValue(vector));

  /// <summary>
  /// Every swizzle property (two to four distinct letters) reads the components named, in order, and writing
  /// the value read back changes nothing; <paramref name="count"/> is how many the type has.
  /// </summary>
  [Theory]
  [InlineData(typeof(Vector4d), 12 + 24 + 23)]  // ordered pairs, triples, and the 24 orders of four but Xyzw (OpenTK has none)
  [InlineData(typeof(Vector4), 12 + 24 + 23)]
  [InlineData(typeof(Vector3), 6 + 5)]          // pairs, and the orders of three but Xyz
  [InlineData(typeof(Vector3d), 6 + 5)]
  [InlineData(typeof(Vector2), 1)]
  [InlineData(typeof(Vector2d), 1)]
  public void Every_swizzle_reads_its_components_in_order_and_writes_them_back(Type type, int count)
  {
    object v = Activator.CreateInstance(type)!;
    foreach (char c in "XYZW".Take(type.GetFields().Count(f => !f.IsStatic)))
      type.GetField(c.ToString())!.SetValue(v, Convert.ChangeType("XYZW".IndexOf(c) + 1, type.GetField(c.ToString())!.FieldType));
    int found = 0;
    foreach (var p in type.GetProperties())
    {
      string name = p.Name;
      if (name.Length < 2 || name.Length > 4 || !name.ToUpperInvariant().All("XYZW".Contains) || name.ToUpperInvariant().Distinct().Count() != name.Length)
        continue;
      object value = p.GetValue(v)!;
      Assert.Equal(name.ToUpperInvariant().Select(c => (double)("XYZW".IndexOf(c) + 1)).ToArray(), name.Select((_, i) => Component(value, "XYZW"[i])).ToArray());
      object before = v.ToString()!;
      p.SetValue(v, value);
      Assert.Equal(before, v.ToString());
      found++;
    }
    Assert.Equal(count, found);
  }

  /// <summary>OpenTK 3's four swizzles that repeat a letter: the getter reads the letters, the setter writes X then the letters after the first.</summary>
  [Theory]
  [InlineData("Yyzw", 2, 2, 3, 4, 10, 20, 30, 40)]
  [InlineData("Yywz", 2, 2, 4, 3, 10, 20, 40, 30)]
  [InlineData("Zwzy", 3, 4, 3, 2, 10, 40, 30, 20)]
  [InlineData("Wzyw", 4, 3, 2, 4, 10, 30, 20, 40)]
  public void Repeating_swizzles_keep_OpenTKs_getter_and_setter(string name, float gx, float gy, float gz, float gw, float sx, float sy, float sz, float sw)
  {
    object f = new Vector4(1, 2, 3, 4), d = new Vector4d(1, 2, 3, 4);
    Assert.Equal(new Vector4(gx, gy, gz, gw), typeof(Vector4).GetProperty(name)!.GetValue(f));
    Assert.Equal(new Vector4d(gx, gy, gz, gw), typeof(Vector4d).GetProperty(name)!.GetValue(d));
    typeof(Vector4).GetProperty(name)!.SetValue(f, new Vector4(10, 20, 30, 40));
    typeof(Vector4d).GetProperty(name)!.SetValue(d, new Vector4d(10, 20, 30, 40));
    Assert.Equal(new Vector4(sx, sy, sz, sw), f);
    Assert.Equal(new Vector4d(sx, sy, sz, sw), d);
  }
}
