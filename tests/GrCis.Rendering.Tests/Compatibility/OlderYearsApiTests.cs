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
}
