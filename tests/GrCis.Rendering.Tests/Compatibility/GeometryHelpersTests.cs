using System;
using System.Collections.Generic;
using System.Linq;
using MathSupport;
using OpenTK.Mathematics;
using Rendering;
using Support;

namespace GrCis.Rendering.Tests.Compatibility;

/// <summary>GrCis's sampling, slab, parsing and small helpers, with values checked by hand.</summary>
public class GeometryHelpersTests
{
  [Fact]
  public void RandomDirectionNormal_gives_unit_vectors_spread_around_the_direction_by_the_variance()
  {
    var rnd = new RandomJames(17);
    var dir = new Vector3d(1, 2, -2);
    Vector3d axis = dir.Normalized();
    var angles = new List<double>();
    for (int i = 0; i < 20000; i++)
    {
      Vector3d v = Geometry.RandomDirectionNormal(rnd, dir, 0.1);
      Assert.Equal(1.0, v.Length, 9);
      angles.Add(Math.Acos(Math.Clamp(Vector3d.Dot(v, axis), -1.0, 1.0)));
    }
    // The angle to the axis is |N(0, 0.1)|: mean 0.1·√(2/π) ≈ 0.0798.
    Assert.InRange(angles.Average(), 0.077, 0.083);
    Vector3d z = Geometry.RandomDirectionNormal(new RandomJames(3), 0.0);
    Assert.True((z - Vector3d.UnitZ).Length < 1e-12);
  }

  [Fact]
  public void RayBoxIntersection_returns_entry_and_exit_or_false()
  {
    Vector3d ul = new(0, 0, 0), size = new(1, 2, 3);
    Vector3d p0 = new(0.5, 1, -1), p1 = new(0, 0, 2);
    Assert.True(Geometry.RayBoxIntersection(ref p0, ref p1, ref ul, ref size, out Vector2d t));
    Assert.Equal(new Vector2d(0.5, 2.0), t);

    Vector3d miss = new(2, 1, -1);
    Assert.False(Geometry.RayBoxIntersection(ref miss, ref p1, ref ul, ref size, out t));
    Assert.Equal(new Vector2d(-1, -1), t);

    Vector3d down = new(0, -1, 0), inside = new(0.5, 1, 1);
    Assert.True(Geometry.RayBoxIntersection(ref inside, ref down, ref ul, ref size, out t));
    Assert.Equal(new Vector2d(-1.0, 1.0), t);   // the entry lies behind the origin

    Vector3d inv = new(double.PositiveInfinity, double.PositiveInfinity, 0.5);
    Vector3 ulf = new(0, 0, 0), sizef = new(1, 2, 3);
    Assert.True(Geometry.RayBoxIntersectionInv(ref p0, ref inv, ref ulf, ref sizef, out t));
    Assert.Equal(new Vector2d(0.5, 2.0), t);
  }

  [Fact]
  public void Vectors_parse_from_text_with_brackets_and_any_separator()
  {
    Assert.Equal(new[] { 1.0, -2.5, 0.0 }, Geometry.TryParseDoubleVector("[1; -2.5; ]"));
    Assert.Equal(new[] { 1f, 2f }, Geometry.TryParseFloatVector("(1:2)"));
    Assert.Equal(new[] { 3.0, 4.0 }, Geometry.TryParseDoubleVector("3,x,4"));
    Assert.Null(Geometry.TryParseDoubleVector("  "));

    var rec = new Dictionary<string, string> { ["c"] = "0.5, 1, 2", ["short"] = "1" };
    var v3 = new Vector3(9, 9, 9);
    Assert.True(Geometry.TryParse(rec, "c", ref v3));
    Assert.Equal(new Vector3(0.5f, 1, 2), v3);
    var v2 = new Vector2d(7, 7);
    Assert.False(Geometry.TryParse(rec, "short", ref v2));
    Assert.Equal(new Vector2d(7, 7), v2);

    var ctx = new Dictionary<string, object> { ["dir"] = new Vector3d(1, 2, 3), ["text"] = "1,2,3,4" };
    Assert.True(Geometry.TryParse(ctx, "dir", ref v3));
    Assert.Equal(new Vector3(1, 2, 3), v3);
    var v4 = new Vector4();
    Assert.True(Geometry.TryParse(ctx, "text", ref v4));
    Assert.Equal(new Vector4(1, 2, 3, 4), v4);
  }

  [Fact]
  public void Small_GrCis_helpers()
  {
    Assert.Equal("Prilis zlutoucky kun", TextUtils.RemoveDiacritics("Příliš žluťoučký kůň"));
    Assert.True(new OperationUnion().Result(false, true));
    Assert.False(new OperationIntersection().Result(false, true));
    Assert.True(new OperationDifference().Result(true, false));
    Assert.False(new OperationXor().Result(true, true));
    var dark = new AmbientLightSource();
    Assert.Equal(new double[3], dark.GetIntensity(new Intersection(), out _));
    Assert.Equal(1.0e6, DefaultSceneNode.INFINITY_PLACEHOLDER);
    Assert.Equal(16807UL, RandomStatic.parkMiller(1UL));
    Assert.Equal(65539UL, RandomStatic.ibmRandu(1UL));
    Assert.Equal(427419669081UL, RandomStatic.maple(1UL));
    ulong next = RandomStatic.numericRecipes(1UL);   // GrCis's unsigned type, whatever the argument's
    Assert.Equal(1015568748UL, next);
  }

  [Theory]
  [InlineData(1.0, 0.0, 0.0, 0.0)]
  [InlineData(0.0, 1.0, 0.0, 120.0)]
  [InlineData(0.0, 0.0, 1.0, 240.0)]
  [InlineData(1.0, 0.0, 1.0, 300.0)]
  [InlineData(0.5, 0.25, 0.0, 30.0)]
  public void HSV_conversions_round_trip(double r, double g, double b, double hue)
  {
    Arith.RGBtoHSV(r, g, b, out double h, out double s, out double v);
    Assert.Equal(hue, h, 9);
    Assert.Equal(System.Math.Max(r, System.Math.Max(g, b)), v);
    Arith.HSVtoRGB(h, s, v, out double r2, out double g2, out double b2);
    Assert.Equal((r, g, b), (System.Math.Round(r2, 9), System.Math.Round(g2, 9), System.Math.Round(b2, 9)));
    Arith.HSVtoRGB(h - 720.0, s, v, out double r3, out _, out _);   // any hue wraps
    Assert.Equal(r, r3, 9);
    System.Drawing.Color c = Arith.HSVToColor(h, s, v);
    Arith.ColorToHSV(c, out double ch, out _, out double cv);
    Assert.Equal(hue, ch, 0);
    Assert.Equal(v, cv, 2);
  }
}
