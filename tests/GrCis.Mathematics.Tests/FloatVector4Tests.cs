using System;
using OpenTK.Mathematics;

namespace GrCis.Mathematics.Tests;

/// <summary>Values of the float Vector4's OpenTK 3 members (Compatibility/Data/opentk3-api.tsv).</summary>
public class FloatVector4Tests
{
  static readonly Vector4 a = new(1, -2, 4, 8), b = new(2, 2, -1, 0.5f);

  /// <summary>Each binary helper, its ref/out twin and the hand-computed value for a = (1, −2, 4, 8), b = (2, 2, −1, 0.5).</summary>
  [Theory]
  [InlineData("Add", 3, 0, 3, 8.5f)]
  [InlineData("Subtract", -1, -4, 5, 7.5f)]
  [InlineData("Multiply", 2, -4, -4, 4)]
  [InlineData("Divide", 0.5f, -1, -4, 16)]
  [InlineData("Min", 1, -2, -1, 0.5f)]
  [InlineData("Max", 2, 2, 4, 8)]
  [InlineData("MagnitudeMin", 2, 2, -1, 0.5f)]
  [InlineData("MagnitudeMax", 1, -2, 4, 8)]
  [InlineData("Lerp", 1.5f, 0, 1.5f, 4.25f)]
  public void Binary_helpers_and_their_ref_out_twins(string op, float x, float y, float z, float w)
  {
    Vector4 l = a, r = b;
    (Vector4 value, Vector4 viaRef) = op switch
    {
      "Add" => (Vector4.Add(a, b), Call(Vector4.Add)),
      "Subtract" => (Vector4.Subtract(a, b), Call(Vector4.Subtract)),
      "Multiply" => (Vector4.Multiply(a, b), Call(Vector4.Multiply)),
      "Divide" => (Vector4.Divide(a, b), Call(Vector4.Divide)),
      "Min" => (Vector4.ComponentMin(a, b), Call(Vector4.Min)),
      "Max" => (Vector4.ComponentMax(a, b), Call(Vector4.Max)),
      "MagnitudeMin" => (Vector4.MagnitudeMin(a, b), Call(Vector4.MagnitudeMin)),
      "MagnitudeMax" => (Vector4.MagnitudeMax(a, b), Call(Vector4.MagnitudeMax)),
      _ => (Vector4.Lerp(a, b, 0.5f), LerpHalf()),
    };
    Assert.Equal(new Vector4(x, y, z, w), value);
    Assert.Equal(value, viaRef);

    Vector4 Call(RefOp f) { f(ref l, ref r, out Vector4 result); return result; }
    Vector4 LerpHalf() { Vector4.Lerp(ref l, ref r, 0.5f, out Vector4 result); return result; }
  }

  delegate void RefOp(ref Vector4 left, ref Vector4 right, out Vector4 result);

  [Fact]
  public void Component_min_max_clamp_dot_and_scalar_forms()
  {
    Vector4 l = a, r = b, lo = Vector4.Zero, hi = new(1, 1, 1, 1);
    Vector4.ComponentMin(ref l, ref r, out Vector4 min);
    Vector4.ComponentMax(ref l, ref r, out Vector4 max);
    Assert.Equal((Vector4.Min(a, b), Vector4.Max(a, b)), (min, max));
    Vector4.Clamp(ref l, ref lo, ref hi, out Vector4 clamped);
    Assert.Equal(new Vector4(1, 0, 1, 1), clamped);
    Vector4.Dot(ref l, ref r, out float dot);
    Assert.Equal(2 - 4 - 4 + 4, dot);
    Vector4.Multiply(ref l, 0.5f, out Vector4 half);
    Vector4.Divide(ref l, 2f, out Vector4 halfToo);
    Assert.Equal(new Vector4(0.5f, -1, 2, 4), half);
    Assert.Equal(half, halfToo);
    Assert.Equal(-half, Vector4.Divide(-a, 2f));
    Vector4 c = Vector4.UnitW;
    Vector4.BaryCentric(ref l, ref r, ref c, 0.25f, 0.5f, out Vector4 bary);
    Assert.Equal(a + 0.25f * (b - a) + 0.5f * (c - a), bary);
  }

  [Theory]
  [InlineData(1, 2, 2, 4)]
  [InlineData(0, 0, -3, 0)]
  public void Normalisation(float x, float y, float z, float w)
  {
    Vector4 v = new(x, y, z, w);
    float length = MathF.Sqrt(x * x + y * y + z * z + w * w);
    Assert.Equal(length, v.LengthFast, 5);
    Vector4 unit = v / length;
    Vector4.Normalize(ref v, out Vector4 n1);
    Vector4.NormalizeFast(ref v, out Vector4 n2);
    foreach (Vector4 n in new[] { n1, n2, Vector4.Normalize(v), Vector4.NormalizeFast(v), v.Normalized() })
      Assert.True((n - unit).Length < 1e-6f, n.ToString());
    v.NormalizeFast();
    Assert.Equal(1, v.Length, 5);
  }

  [Fact]
  public void Matrix_on_the_left_multiplies_a_column_and_equals_the_transpose_on_the_right()
  {
    Matrix4 m = Matrix4.CreateFromAxisAngle(new Vector3(1, 2, 3), 0.8f) * Matrix4.CreateTranslation(4, 5, 6);
    m.Row0.W = 0.25f;
    Vector4 v = a;
    Vector4.Transform(ref m, ref v, out Vector4 column);
    Assert.Equal(Vector4.Dot(m.Row2, a), column.Z);
    Assert.Equal(column, m * a);
    Assert.True((column - a * m.Transposed()).Length < 1e-4f, $"{column} vs {a * m.Transposed()}");
    Assert.Equal(new Vector4(1, 2, 3, 4), Matrix4.Identity * new Vector4(1, 2, 3, 4));
  }

  [Fact]
  public void Constructors_indexer_and_constants()
  {
    Assert.Equal(new Vector4(1, 2, 0, 0), new Vector4(new Vector2(1, 2)));
    Assert.Equal(new Vector4(1, 2, 3, 0), new Vector4(new Vector3(1, 2, 3)));
    Assert.Equal(a, new Vector4(a));
    Assert.Equal(new Vector4(2, 2, 2, 2), new Vector4(2));
    Assert.Equal(Vector4.One, Vector4.UnitX + Vector4.UnitY + Vector4.UnitZ + Vector4.UnitW);
    Vector4 v = a;
    v[3] = 9;
    Assert.Equal((1f, -2f, 4f, 9f), (v[0], v[1], v[2], v[3]));
    Assert.Throws<IndexOutOfRangeException>(() => v[4]);
    Assert.Equal(16, Vector4.SizeInBytes);
  }
}
