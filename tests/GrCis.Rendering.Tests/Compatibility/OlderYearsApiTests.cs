using System;
using System.Collections.Generic;
using MathSupport;
using Rendering;
using Utilities;

namespace GrCis.Rendering.Tests.Compatibility;

/// <summary>Members only older GrCis course years had (see <see cref="ApiYearsTests"/>), kept under their old names with their old meaning.</summary>
public class OlderYearsApiTests
{
  [Theory]
  [InlineData(0.0, 1.0, 1.0)]
  [InlineData(200.0, 0.5, 0.8)]
  [InlineData(359.0, 0.25, 2.0)]
  public void HSVToRGB_gives_the_same_colour_as_HSVtoRGB(double hue, double saturation, double value)
  {
    Arith.HSVToRGB(hue, saturation, value, out double r1, out double g1, out double b1);
    Arith.HSVtoRGB(hue, saturation, value, out double r2, out double g2, out double b2);
    Assert.Equal((r2, g2, b2), (r1, g1, b1));
  }

  [Fact]
  public void HSVToRGB_of_pure_hues_gives_the_primaries()
  {
    Arith.HSVToRGB(120.0, 1.0, 1.0, out double r, out double g, out double b);
    Assert.Equal((0.0, 1.0, 0.0), (r, g, b));
  }

  [Fact]
  public void TryParseInt_reads_an_integer_parameter_and_leaves_the_value_when_it_cannot()
  {
    Dictionary<string, string> p = Util.ParseKeyValueList("n=12, bad=x");
    int n = 5;
    Assert.True(Util.TryParseInt(p, "n", ref n));
    Assert.Equal(12, n);
    Assert.False(Util.TryParseInt(p, "bad", ref n));
    Assert.False(Util.TryParseInt(p, "missing", ref n));
    Assert.Equal(12, n);
  }

  [Fact]
  public void Scenes_Repository_is_the_scene_repository_under_its_2016_name()
  {
    Assert.Same(Scenes.staticRepository, Scenes.Repository);
    Assert.IsType<InitSceneDelegate>(Scenes.Repository["Five balls"]);
    Assert.IsType<InitSceneParamDelegate>(Scenes.Repository["Sphere flake"]);
  }

  [Fact]
  public void BezierSurface_Epsilon_static_until_2020_and_per_surface_since_set_one_shared_threshold()
  {
    double old = BezierSurface.Epsilon;
    // The next double up: a distinct value that subdivides every surface exactly as the old one, so tests running alongside see no change.
    double other = Math.BitIncrement(old);
    var surface = new BezierSurface(1, 1, FlatPatch());
    try
    {
      BezierSurface.Epsilon = other;          // GrCis until May 2020
      Assert.Equal(other, surface.Epsilon);
      surface.Epsilon = old;                  // GrCis since June 2020
      Assert.Equal(old, BezierSurface.Epsilon);
      var initialized = new BezierSurface(1, 1, FlatPatch()) { Epsilon = other };
      Assert.Equal(other, BezierSurface.Epsilon);
      Assert.Equal(other, initialized.Epsilon);
    }
    finally
    {
      BezierSurface.Epsilon = old;
    }
  }

  /// <summary>One flat bicubic patch over [0, 3]².</summary>
  static double[] FlatPatch()
  {
    var net = new double[16 * 3];
    for (int i = 0; i < 16; i++)
    {
      net[3 * i] = i % 4;
      net[3 * i + 1] = i / 4;
    }
    return net;
  }
}
