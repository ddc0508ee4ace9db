using System;
using OpenTK.Mathematics;

namespace GrCis.Mathematics.Tests;

/// <summary>Values of the float Vector2's OpenTK 3 members (Compatibility/Data/opentk3-api.tsv).</summary>
public class FloatVector2Tests
{
  static readonly Vector2 a = new(3, -4), b = new(0.5f, 2);

  /// <summary>Each ref/out twin against the hand-computed value of a = (3, −4), b = (0.5, 2).</summary>
  [Theory]
  [InlineData("Add", 3.5f, -2)]
  [InlineData("Subtract", 2.5f, -6)]
  [InlineData("Multiply", 1.5f, -8)]
  [InlineData("Divide", 6, -2)]
  [InlineData("ComponentMin", 0.5f, -4)]
  [InlineData("ComponentMax", 3, 2)]
  [InlineData("MagnitudeMin", 0.5f, 2)]
  [InlineData("MagnitudeMax", 3, -4)]
  [InlineData("Lerp", 1.75f, -1)]
  [InlineData("ScaleBy2", 6, -8)]
  [InlineData("HalveBy2", 1.5f, -2)]
  public void Ref_out_twins_give_hand_computed_values(string op, float x, float y)
  {
    Vector2 l = a, r = b, result;
    switch (op)
    {
      case "Add": Vector2.Add(ref l, ref r, out result); Assert.Equal(Vector2.Add(a, b), result); break;
      case "Subtract": Vector2.Subtract(ref l, ref r, out result); Assert.Equal(Vector2.Subtract(a, b), result); break;
      case "Multiply": Vector2.Multiply(ref l, ref r, out result); Assert.Equal(Vector2.Multiply(a, b), result); break;
      case "Divide": Vector2.Divide(ref l, ref r, out result); Assert.Equal(Vector2.Divide(a, b), result); break;
      case "ComponentMin": Vector2.ComponentMin(ref l, ref r, out result); Assert.Equal(Vector2.ComponentMin(a, b), result); break;
      case "ComponentMax": Vector2.ComponentMax(ref l, ref r, out result); Assert.Equal(Vector2.ComponentMax(a, b), result); break;
      case "MagnitudeMin": Vector2.MagnitudeMin(ref l, ref r, out result); Assert.Equal(Vector2.Min(a, b), result); break;
      case "MagnitudeMax": Vector2.MagnitudeMax(ref l, ref r, out result); Assert.Equal(Vector2.Max(a, b), result); break;
      case "Lerp": Vector2.Lerp(ref l, ref r, 0.5f, out result); Assert.Equal(Vector2.Lerp(a, b, 0.5f), result); break;
      case "ScaleBy2": Vector2.Multiply(ref l, 2f, out result); Assert.Equal(2 * a, result); break;
      default: Vector2.Divide(ref l, 2f, out result); Assert.Equal(Vector2.Divide(a, 2f), result); break;
    }
    Assert.Equal(new Vector2(x, y), result);
  }

  [Fact]
  public void Scalar_results_dot_perpdot_and_distances()
  {
    Vector2 l = a, r = b;
    Vector2.Dot(ref l, ref r, out float dot);
    Vector2.PerpDot(ref l, ref r, out float perp);
    Vector2.Distance(ref l, ref r, out float dist);
    Vector2.DistanceSquared(ref l, ref r, out float dist2);
    Assert.Equal((-6.5f, 8f, 42.25f), (dot, perp, dist2));
    Assert.Equal(6.5f, dist, 5);
    Assert.Equal(Vector2.PerpDot(a, b), Vector3.Cross(new Vector3(a), new Vector3(b)).Z);
    Assert.Equal(0, Vector2.Dot(a, a.PerpendicularLeft));
    Assert.Equal(-a, a.PerpendicularLeft.PerpendicularLeft);
    Assert.Equal(a, a.PerpendicularRight.PerpendicularLeft);
  }

  [Fact]
  public void Normalisation_clamp_barycentric_and_members()
  {
    Vector2 v = a, unit = new(0.6f, -0.8f);
    Assert.Equal(5, v.LengthFast, 5);
    Vector2.Normalize(ref v, out Vector2 n1);
    Vector2.NormalizeFast(ref v, out Vector2 n2);
    v.NormalizeFast();
    foreach (Vector2 n in new[] { n1, n2, v, Vector2.NormalizeFast(a), Vector2.Normalize(a) })
      Assert.True((n - unit).Length < 1e-6f, n.ToString());
    Vector2 lo = Vector2.Zero, hi = Vector2.One, c = new(1, 1), l = a, r = b;
    Vector2.Clamp(ref l, ref lo, ref hi, out Vector2 clamped);
    Assert.Equal(new Vector2(1, 0), clamped);
    Vector2.BaryCentric(ref l, ref r, ref c, 0.5f, 0.25f, out Vector2 bary);
    Assert.Equal(a + 0.5f * (b - a) + 0.25f * (c - a), bary);
    Assert.Equal(new Vector2(7, 7), new Vector2(7));
    Vector2 w = new(1, 2) { [0] = 5 };
    w.Yx = w;
    Assert.Equal((2f, 5f), (w[0], w[1]));
    Assert.Throws<IndexOutOfRangeException>(() => w[2]);
    Assert.Equal(8, Vector2.SizeInBytes);
    Assert.Equal((Vector2.UnitX + Vector2.UnitY, Vector2.Zero), (Vector2.One, Vector2.One - Vector2.One));
  }
}
