using System.Collections.Generic;
using Utilities;

namespace GrCis.Rendering.Tests.Utilities;

public class UtilTests
{
  [Fact]
  public void ParseKeyValueList_trims_keys_and_values_and_keeps_bare_keys()
  {
    Dictionary<string, string> p = Util.ParseKeyValueList(" n = 1.5 , mat=glass,,rc, depth=4");
    Assert.Equal(4, p.Count);
    Assert.Equal("1.5", p["n"]);
    Assert.Equal("glass", p["mat"]);
    Assert.Equal("", p["rc"]);
    Assert.Equal("4", p["depth"]);
  }

  [Fact]
  public void ParseKeyValueList_later_duplicate_wins_and_empty_key_is_skipped()
  {
    Dictionary<string, string> p = Util.ParseKeyValueList("n=1,=7,n=2");
    Assert.Single(p);
    Assert.Equal("2", p["n"]);
  }

  [Fact]
  public void ParseKeyValueList_of_null_or_empty_is_empty()
  {
    Assert.Empty(Util.ParseKeyValueList(null));
    Assert.Empty(Util.ParseKeyValueList(""));
  }

  [Fact]
  public void ParseKeyValueList_honours_a_custom_separator()
  {
    Dictionary<string, string> p = Util.ParseKeyValueList("a=1;b=x,y", ';');
    Assert.Equal("1", p["a"]);
    Assert.Equal("x,y", p["b"]);
  }

  [Fact]
  public void TryParse_reads_numbers_with_the_invariant_culture()
  {
    var p = Util.ParseKeyValueList("n=1.6,depth=5,big=12345678901,e=1e3");
    double n = 0;
    int depth = 0;
    long big = 0;
    float e = 0;
    Assert.True(Util.TryParse(p, "n", ref n));
    Assert.True(Util.TryParse(p, "depth", ref depth));
    Assert.True(Util.TryParse(p, "big", ref big));
    Assert.True(Util.TryParse(p, "e", ref e));
    Assert.Equal(1.6, n);
    Assert.Equal(5, depth);
    Assert.Equal(12345678901L, big);
    Assert.Equal(1000f, e);
  }

  [Fact]
  public void TryParse_of_a_bad_value_returns_false_and_keeps_the_default()
  {
    var p = Util.ParseKeyValueList("n=abc,depth=2.5");
    double n = 1.6;
    int depth = 5;
    Assert.False(Util.TryParse(p, "n", ref n));
    Assert.False(Util.TryParse(p, "depth", ref depth));
    Assert.False(Util.TryParse(p, "missing", ref n));
    Assert.False(Util.TryParse((Dictionary<string, string>?)null, "n", ref n));
    Assert.Equal(1.6, n);
    Assert.Equal(5, depth);
  }

  [Theory]
  [InlineData("rc", true)]
  [InlineData("rc=1", true)]
  [InlineData("rc=yes", true)]
  [InlineData("rc=true", true)]
  [InlineData("rc=on", true)]
  [InlineData("rc=0", false)]
  [InlineData("rc=no", false)]
  [InlineData("rc=false", false)]
  [InlineData("other", false)]
  public void TryParseBool_counts_a_bare_key_as_true(string param, bool expected)
  {
    Assert.Equal(expected, Util.TryParseBool(Util.ParseKeyValueList(param), "rc"));
  }

  [Fact]
  public void TryParse_bool_rejects_gibberish()
  {
    bool b = true;
    Assert.False(Util.TryParse(Util.ParseKeyValueList("rc=maybe"), "rc", ref b));
    Assert.True(b);
  }

  [Fact]
  public void TryParse_string_returns_the_trimmed_text()
  {
    string mat = "glass";
    Assert.True(Util.TryParse(Util.ParseKeyValueList("mat= mirror "), "mat", ref mat));
    Assert.Equal("mirror", mat);
  }

  [Fact]
  public void Context_TryParse_converts_between_numeric_types()
  {
    var ctx = new Dictionary<string, object> { ["Width"] = 640, ["Fps"] = 25, ["Time"] = 2.5, ["Text"] = "7", ["Frac"] = 2.5 };
    int w = 0;
    double fps = 0, time = 0;
    long text = 0;
    int frac = 3;
    Assert.True(Util.TryParse(ctx, "Width", ref w));
    Assert.True(Util.TryParse(ctx, "Fps", ref fps));
    Assert.True(Util.TryParse(ctx, "Time", ref time));
    Assert.True(Util.TryParse(ctx, "Text", ref text));
    Assert.False(Util.TryParse(ctx, "Frac", ref frac));
    Assert.Equal(640, w);
    Assert.Equal(25.0, fps);
    Assert.Equal(2.5, time);
    Assert.Equal(7L, text);
    Assert.Equal(3, frac);
  }

  [Fact]
  public void Context_TryParse_of_a_wrong_type_returns_false()
  {
    var ctx = new Dictionary<string, object> { ["Width"] = new object(), ["Name"] = "x" };
    int w = 1;
    double d = 2;
    Assert.False(Util.TryParse(ctx, "Width", ref w));
    Assert.False(Util.TryParse(ctx, "Name", ref d));
    Assert.Equal(1, w);
    Assert.Equal(2, d);
  }

  [Fact]
  public void Context_TryParseBool_reads_bools_and_text()
  {
    var ctx = new Dictionary<string, object> { ["Preprocessing"] = true, ["No"] = false, ["Text"] = "yes" };
    Assert.True(Util.TryParseBool(ctx, "Preprocessing"));
    Assert.False(Util.TryParseBool(ctx, "No"));
    Assert.True(Util.TryParseBool(ctx, "Text"));
    Assert.False(Util.TryParseBool(ctx, "Missing"));
    Assert.False(Util.TryParseBool((Dictionary<string, object>?)null, "Missing"));
  }

  [Fact]
  public void Context_TryParse_string_formats_non_strings_invariantly()
  {
    var ctx = new Dictionary<string, object> { ["SceneName"] = "Two spheres", ["Time"] = 1.5 };
    string name = "", time = "";
    Assert.True(Util.TryParse(ctx, "SceneName", ref name));
    Assert.True(Util.TryParse(ctx, "Time", ref time));
    Assert.Equal("Two spheres", name);
    Assert.Equal("1.5", time);
  }

  [Fact]
  public void ColorClone_copies_and_scales_without_aliasing()
  {
    double[] c = { 0.2, 0.4, 0.6 };
    double[] copy = Util.ColorClone(c)!;
    double[] half = Util.ColorClone(c, 0.5)!;
    copy[0] = 9;
    Assert.Equal(0.2, c[0]);
    Assert.Equal(new[] { 0.1, 0.2, 0.3 }, half);
    Assert.Null(Util.ColorClone(null));
  }

  [Fact]
  public void Color_helpers_add_multiply_and_copy_over_common_bands()
  {
    double[] dst = { 1, 1, 1 };
    Util.ColorAdd(new[] { 1.0, 2.0, 3.0 }, dst);
    Assert.Equal(new[] { 2.0, 3.0, 4.0 }, dst);
    Util.ColorAdd(new[] { 1.0, 1.0, 1.0 }, 0.5, dst);
    Assert.Equal(new[] { 2.5, 3.5, 4.5 }, dst);
    Util.ColorAdd(new[] { 2.0, 2.0, 2.0 }, new[] { 1.0, 0.0, 0.5 }, dst);
    Assert.Equal(new[] { 4.5, 3.5, 5.5 }, dst);
    Util.ColorAdd(0.5, dst);
    Assert.Equal(new[] { 5.0, 4.0, 6.0 }, dst);
    Util.ColorMul(0.5, dst);
    Assert.Equal(new[] { 2.5, 2.0, 3.0 }, dst);
    Util.ColorMul(new[] { 2.0, 0.5, 1.0 }, dst);
    Assert.Equal(new[] { 5.0, 1.0, 3.0 }, dst);
    Util.ColorCopy(new[] { 7.0, 8.0 }, dst);
    Assert.Equal(new[] { 7.0, 8.0, 0.0 }, dst);
    Util.ColorCopy(new[] { 1.0, 2.0, 3.0 }, 2.0, dst);
    Assert.Equal(new[] { 2.0, 4.0, 6.0 }, dst);
  }
}
