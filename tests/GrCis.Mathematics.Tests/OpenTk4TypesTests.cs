using System;
using System.Globalization;
using OpenTK.Mathematics;
using Half = OpenTK.Mathematics.Half;

namespace GrCis.Mathematics.Tests;

/// <summary>OpenTK's boxes, half-precision float and Bézier curve.</summary>
public class OpenTk4TypesTests
{
  [Fact]
  public void Box_constructor_orders_the_corners_and_setters_drag_the_other_corner()
  {
    Box3 b = new(new Vector3(4, 0, 1), new Vector3(1, 2, -1));
    Assert.Equal((new Vector3(1, 0, -1), new Vector3(4, 2, 1)), (b.Min, b.Max));
    Assert.Equal(new Vector3(3, 2, 2), b.Size);
    Assert.Equal(new Vector3(2.5f, 1, 0), b.Center);
    b.Min = new Vector3(5, 0, -1);
    Assert.Equal(new Vector3(5, 2, 1), b.Max);
    Box2d d = new(3, 3, 1, 1);
    d.Max = new Vector2d(0, 5);
    Assert.Equal((new Vector2d(0, 1), new Vector2d(0, 5)), (d.Min, d.Max));
  }

  [Fact]
  public void Box_contains_tells_inside_boundary_and_overlap()
  {
    Box2 b = new(0, 0, 2, 2);
    Assert.True(b.ContainsExclusive(new Vector2(1, 1)));
    Assert.False(b.ContainsExclusive(new Vector2(2, 1)));
    Assert.True(b.ContainsInclusive(new Vector2(2, 1)));
    Assert.True(b.Contains(new Vector2(2, 1), true));
    Assert.False(b.Contains(new Vector2(2, 1)));
    Assert.True(b.Contains(new Box2(2, 2, 5, 5)));
    Assert.False(b.Contains(new Box2(2.5f, 0, 5, 5)));
    Assert.Equal(0, b.DistanceToNearestEdge(new Vector2(1, 1)));
    Assert.Equal(5, b.DistanceToNearestEdge(new Vector2(5, 6)));
    Box3d c = new(Vector3d.Zero, Vector3d.One);
    Assert.True(c.ContainsInclusive(Vector3d.One));
  }

  [Fact]
  public void Box_moves_scales_inflates_and_extends()
  {
    Box3 b = new(Vector3.Zero, new Vector3(2, 2, 2));
    Assert.Equal(new Box3(Vector3.One, new Vector3(3)), b.Translated(Vector3.One));
    Assert.Equal(new Box3(new Vector3(-1), new Vector3(3)), b.Scaled(new Vector3(2), Vector3.One));
    Assert.Equal(new Box3(new Vector3(-1), new Vector3(3)), b.Inflated(Vector3.One));
    // Shrinking stops at the centre.
    Assert.Equal(new Box3(Vector3.One, Vector3.One), b.Inflated(new Vector3(-5)));
    Assert.Equal(new Box3(Vector3.Zero, new Vector3(2, 7, 2)), b.Extended(new Vector3(1, 7, 1)));
    b.Size = new Vector3(4, 2, 2);
    Assert.Equal(new Vector3(-1, 0, 0), b.Min);
    b.Center = Vector3.Zero;
    Assert.Equal(new Vector3(2, 1, 1), b.Max);
    Box2 s = new(0, 0, 1, 1);
    s.HalfSize = new Vector2(1, 1);
    Assert.Equal(new Vector2(1.5f, 1.5f), s.Max);
    Assert.Equal("(0, 0) - (1, 1)", new Box2(0, 0, 1, 1).ToString(CultureInfo.InvariantCulture));
  }

  [Fact]
  public void Half_round_trips_every_bit_pattern_and_names_the_specials()
  {
    for (int bits = short.MinValue; bits <= short.MaxValue; bits++)
    {
      Half h = Half.FromBytes(BitConverter.GetBytes((short)bits), 0);
      Half back = new((float)h);
      Assert.True(h.IsNaN ? back.IsNaN : h == back, $"{bits:x4}");
      Assert.Equal(((float)h).ToString(CultureInfo.CurrentCulture), h.ToString());
    }
    for (int i = -2048; i <= 2048; i++)
      Assert.Equal(i, (float)new Half((float)i));
    Assert.True(new Half(float.NaN).IsNaN);
    Assert.True(new Half(float.PositiveInfinity).IsPositiveInfinity);
    Assert.True(new Half(1e6f).IsPositiveInfinity);
    Assert.True(new Half(-1e6).IsNegativeInfinity);
    Assert.Throws<ArithmeticException>(() => new Half(1e6f, true));
    Assert.Equal(new Half(0f), new Half(-0f));
    Assert.Equal(new byte[] { 0x00, 0x3c }, Half.GetBytes(new Half(1f)));
    Assert.Equal(65504f, Half.MaxValue);
  }

  [Fact]
  public void Bezier_curve_runs_from_first_to_last_point_and_parallel_moves_it_right()
  {
    BezierCurve line = new(Vector2.Zero, new Vector2(4, 0));
    Assert.Equal(new Vector2(2, 0), line.CalculatePoint(0.5f));
    Assert.Equal(4, line.CalculateLength(0.25f));
    BezierCurve arc = new(new Vector2(0, 0), new Vector2(1, 2), new Vector2(2, 0));
    Assert.Equal(new Vector2(0, 0), arc.CalculatePoint(0));
    Assert.Equal(new Vector2(2, 0), arc.CalculatePoint(1));
    // Quadratic: the middle is a quarter, half, quarter mix of the three points.
    Assert.Equal(new Vector2(1, 1), arc.CalculatePoint(0.5f));
    Assert.Equal(3, arc.Points.Count);
    BezierCurve shifted = new(1f, Vector2.Zero, new Vector2(4, 0));
    Assert.Equal(new Vector2(0, -1), shifted.CalculatePoint(0));
  }

  static void Near(Color4 expected, Color4 actual, float eps = 1e-5f) =>
    Assert.True(MathF.Abs(expected.R - actual.R) <= eps && MathF.Abs(expected.G - actual.G) <= eps
      && MathF.Abs(expected.B - actual.B) <= eps && expected.A == actual.A, $"{expected} != {actual}");

  [Theory]
  [InlineData(0.2f, 0.5f, 0.9f)]
  [InlineData(1f, 0f, 0f)]
  [InlineData(0.3f, 0.3f, 0.3f)]
  [InlineData(0.9f, 0.8f, 0.1f)]
  public void Color4_round_trips_through_every_colour_space(float r, float g, float b)
  {
    Color4 c = new(r, g, b, 0.5f);
    Near(c, Color4.FromSrgb(Color4.ToSrgb(c)));
    Near(c, Color4.FromHsl(Color4.ToHsl(c)));
    Near(c, Color4.FromHsv(Color4.ToHsv(c)));
    Near(c, Color4.FromHcy(Color4.ToHcy(c)));
    Near(c, Color4.FromYcbcr(Color4.ToYcbcr(c)));
    Near(c, Color4.FromXyz(Color4.ToXyz(c)), 1e-4f);
  }

  [Fact]
  public void Color4_spaces_give_the_textbook_values()
  {
    // Float literals: integer constants would pick the byte constructor (as with OpenTK's Color4).
    Vector4 hsv = Color4.ToHsv(new Color4(0f, 1f, 0f, 1f));
    Assert.Equal((MathF.Round(1f / 3, 6), 1f, 1f, 1f), (MathF.Round(hsv.X, 6), hsv.Y, hsv.Z, hsv.W));
    Vector4 hsl = Color4.ToHsl(new Color4(1f, 0f, 0f, 1f));
    Assert.Equal(new Vector4(0, 1, 0.5f, 1), hsl);
    Assert.Equal(0.5f, Color4.ToSrgb(new Color4(0.21404114f, 0f, 0f, 1f)).R, 5);
    Assert.Equal(1, Color4.ToYcbcr(new Color4(1f, 1f, 1f, 1f)).X, 5);
  }

  [Fact]
  public void Color4_named_colours_bytes_and_argb()
  {
    Assert.Equal(new Color4(1f, 0f, 0f, 1f), Color4.Red);
    Assert.Equal(new Color4((byte)100, (byte)149, (byte)237, (byte)255), Color4.CornflowerBlue);
    Assert.Equal(0, Color4.Transparent.A);
    Assert.Equal(unchecked((int)0xFF6495ED), Color4.CornflowerBlue.ToArgb());
    Assert.Equal(new Vector4(1, 1, 0, 1), (Vector4)Color4.Yellow);
    Color4 fromDrawing = System.Drawing.Color.FromArgb(255, 0, 128, 255);
    Assert.Equal(128 / 255f, fromDrawing.G);
    Assert.Equal("{(R, G, B, A) = (1, 0, 0, 1)}", Color4.Red.ToString(CultureInfo.InvariantCulture));
  }
}
