using System;
using Utilities;

namespace GrCis.Rendering.Tests.Utilities;

/// <summary>GrCis's version helpers and its HTML/D3 snippets.</summary>
public class UtilEnvironmentTests
{
  [Fact]
  public void Versions_describe_this_runtime()
  {
    Util.GetFrameworkVersions(out string target, out string running);
    Assert.StartsWith(".NET", target);
    Assert.Equal(Environment.Version.ToString(), running);
    Assert.False(Util.IsRunningOnMono);
    Assert.Equal(typeof(Util).Assembly.GetName().Version!.ToString(), Util.AssemblyVersion(typeof(Util)));
    string old = Util.ProgramVersion;
    try
    {
      Assert.Equal("Rev: 980", Util.SetVersion("$Rev: 980 $"));
      Assert.Equal("Rev: 980", Util.ProgramVersion);
      Assert.Equal(target, Util.TargetFramework);
    }
    finally
    {
      Util.ProgramVersion = old;
    }
  }

  [Theory]
  [InlineData(255f, 0f, 16.4f, "#FF0010")]
  [InlineData(300f, -5f, 127.5f, "#FF0080")]
  public void d3HexColor_rounds_and_clamps(float r, float g, float b, string expected) =>
    Assert.Equal(expected, Util.d3HexColor(r, g, b));

  [Fact]
  public void D3_palettes_list_their_colours()
  {
    Assert.Equal("d3.scale.ordinal().range([\"#000000\",\"#808080\",\"#FFFFFF\"])", Util.d3LinearPalette(3, 0, 0, 0, 255, 255, 255));
    Assert.Equal("d3.scale.ordinal().range([\"#0A141E\"])", Util.d3LinearPalette(1, new[] { 10, 20, 30, 0, 0, 0 }));
    Assert.Equal("d3.scale.ordinal().range([\"#010203\",\"#FF0000\"])",
      Util.d3DiscretePalette(new[] { Tuple.Create((byte)1, (byte)2, (byte)3), Tuple.Create((byte)255, (byte)0, (byte)0) }));
    Assert.Equal("scale5()", Util.d3ColorPalette(5));
    Assert.Equal("d3.scale.category10()", Util.d3ColorPalette(6));
    Assert.Equal("d3.scale.category20()", Util.d3ColorPalette(11));
  }

  [Theory]
  [InlineData(12.6, "<b>13</b>")]
  [InlineData(0.0, "0")]
  [InlineData(-3.2, "-3")]
  public void CompactFloatHTML_bolds_positive_numbers(double a, string expected) =>
    Assert.Equal(expected, Util.CompactFloatHTML(a));

  [Fact]
  public void Html_marks_follow_good_or_bad()
  {
    Assert.Equal("greent", Util.GreenRedClass(true));
    Assert.Equal("redt", Util.GreenRedClass(false));
    Assert.Equal("&uarr;", Util.UpDownArrow(true));
    Assert.Equal("&darr;", Util.UpDownArrow(false));
  }
}
