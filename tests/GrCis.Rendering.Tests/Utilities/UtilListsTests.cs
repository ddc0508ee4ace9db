using System;
using System.Collections.Generic;
using Utilities;

namespace GrCis.Rendering.Tests.Utilities;

/// <summary>GrCis's list parsers, fractions of pi and map look-ups.</summary>
public class UtilListsTests
{
  [Theory]
  [InlineData("1, 2,3", new[] { 1, 2, 3 })]
  [InlineData("[4,5]", new[] { 4, 5 })]
  [InlineData("7", new[] { 7 })]
  [InlineData("1,,3", new[] { 1, 0, 3 })]
  public void ParseIntList_reads_plain_and_bracketed_lists(string text, int[] expected) =>
    Assert.Equal(expected, Util.ParseIntList(text));

  [Theory]
  [InlineData("1,x,3")]
  [InlineData("1.5")]
  [InlineData("")]
  [InlineData(null)]
  public void ParseIntList_fails_on_any_bad_item(string? text) => Assert.Null(Util.ParseIntList(text));

  [Fact]
  public void Real_lists_are_invariant_and_honour_the_separator()
  {
    Assert.Equal(new[] { 0.5, -2.0, 1e3 }, Util.ParseDoubleList("[0.5; -2; 1e3]", ';'));
    Assert.Equal(new[] { 1.25f, 0f }, Util.ParseFloatList("1.25,"));
    Assert.Null(Util.ParseDoubleList("1,5;2", ';'));
  }

  [Fact]
  public void String_and_id_lists_are_sets()
  {
    Assert.Equal(new HashSet<string> { "a", "b c" }, Util.ParseStringList("[a, b c, a]"));
    Assert.Equal(new HashSet<string> { "x", "y" }, Util.ParseStringList("'x', \"y\"", quotes: true));
    Assert.Equal(new HashSet<string> { "12", "-3" }, Util.ParseIdList("12, abc, -3"));
    Assert.Null(Util.ParseIdList("abc, def"));
    Assert.Null(Util.ParseStringList(""));
    Assert.Equal("'x\"", Util.ParseString("'x\""));
    Assert.Equal(new[] { "a", "", "b" }, Util.ParseList(" a ;; b", ';'));
  }

  [Theory]
  [InlineData("0.25", 0.25)]
  [InlineData("3/4", 0.75)]
  [InlineData("/4", 0.25)]
  [InlineData("1/0", 1.0)]
  [InlineData("pi", Math.PI)]
  [InlineData("-pi", -Math.PI)]
  [InlineData("2pi", 2 * Math.PI)]
  [InlineData("1/3pi", Math.PI / 3)]
  [InlineData("pi/4", Math.PI / 4)]
  [InlineData("-3pi/2", -1.5 * Math.PI)]
  public void ParseRational_reads_fractions_and_multiples_of_pi(string text, double expected)
  {
    double v = double.NaN;
    Assert.True(Util.ParseRational(text, ref v));
    Assert.Equal(expected, v, 12);
  }

  [Theory]
  [InlineData("")]
  [InlineData("x/2")]
  [InlineData("half")]
  public void ParseRational_of_bad_text_keeps_the_value(string text)
  {
    double v = 7.0;
    Assert.False(Util.ParseRational(text, ref v));
    Assert.Equal(7.0, v);
  }

  [Theory]
  [InlineData("12", true, 12)]
  [InlineData("10-20", true, 15)]
  [InlineData("5-", true, 5)]
  [InlineData("-9", true, 9)]
  [InlineData("a-b", false, 3)]
  [InlineData("ten", false, 3)]
  public void TryParseIntRange_takes_the_middle_of_a_range(string text, bool ok, int expected)
  {
    int v = 3;
    Assert.Equal(ok, Util.TryParseIntRange(new Dictionary<string, string> { ["n"] = text }, "n", ref v));
    Assert.Equal(expected, v);
  }

  [Theory]
  [InlineData("255,0,51", 1f, 0f, 0.2f)]
  [InlineData("[300, -4, 0]", 1f, 0f, 0f)]
  [InlineData("2.5, 0.5, -1", 2.5f, 0.5f, 0f)]
  public void TryParse_colour_scales_bytes_and_keeps_HDR_reals(string text, float r, float g, float b)
  {
    float R = -1, G = -1, B = -1;
    Assert.True(Util.TryParse(new Dictionary<string, string> { ["c"] = text }, "c", ref R, ref G, ref B));
    Assert.Equal(r, R, 5);
    Assert.Equal(g, G, 5);
    Assert.Equal(b, B, 5);
  }

  [Fact]
  public void Map_look_ups_of_lists_keep_the_old_value_on_failure()
  {
    var p = Util.ParseKeyValueList("d=[1;2.5],i=x,f=0.5;1,c=1;2,r=pi/2");
    var d = new List<double>();
    var i = new List<int> { 9 };
    var f = new List<float>();
    float R = 0, G = 0, B = 0;
    double r = 0;
    Assert.True(Util.TryParse(p, "d", ref d, ';'));
    Assert.False(Util.TryParse(p, "i", ref i));
    Assert.True(Util.TryParse(p, "f", ref f, ';'));
    Assert.False(Util.TryParse(p, "c", ref R, ref G, ref B, ';'));
    Assert.True(Util.TryParseRational(p, "r", ref r));
    Assert.Equal(new[] { 1.0, 2.5 }, d);
    Assert.Equal(new[] { 9 }, i);
    Assert.Equal(new[] { 0.5f, 1f }, f);
    Assert.Equal(Math.PI / 2, r, 12);
  }

  [Fact]
  public void FirstDefined_variants_pick_by_presence_content_letters_or_digits()
  {
    var rec = new Dictionary<string, string> { ["a"] = "", ["b"] = "42x", ["c"] = "xy7" };
    string[] keys = { "z", "a", "b", "c" };
    Assert.Equal("", Util.FirstDefined(rec, keys));
    Assert.Equal("42x", Util.FirstDefinedNonempty(rec, keys));
    Assert.Equal("b", Util.FirstDefinedKey(rec, keys));
    Assert.Equal("xy", Util.FirstDefinedLetters(rec, keys));
    Assert.Equal("42", Util.FirstDefinedInteger(rec, keys));
    Assert.Null(Util.FirstDefined(rec, new[] { "z" }));
  }

  [Fact]
  public void ParseList_of_pairs_prefixes_keys_and_skips_empty_values_unless_asked()
  {
    var list = new List<KeyValuePair<string, string>>();
    Util.ParseList(list, "q.", "?a=1&&b=&c&=9&d=x=y", 1);
    Assert.Equal(new[] { Util.Pair("q.a", 1), Util.Pair("q.d", "x=y") }, list);
    list.Clear();
    Util.ParseList(list, "", "a=1;b=;c", 0, keepEmpty: true, separator: ';');
    Assert.Equal(new[] { Util.Pair("a", "1"), Util.Pair("b", ""), Util.Pair("c", "") }, list);
    Assert.Equal("2.5", Util.Pair("k", 2.5).Value);
  }

  [Fact]
  public void Small_collection_helpers()
  {
    Assert.Equal(Tuple.Create((byte)255, (byte)0, (byte)7), Util.ColorTuple("300", "x", " 7"));
    Assert.Null(Util.GetFirst(new HashSet<string>()));
    Assert.Equal("only", Util.GetFirst(new HashSet<string> { "only" }));
    Assert.Equal(2, Util.IntersectionSize(new[] { 1, 2, 3 }, new List<int> { 2, 3, 4 }));
  }
}
