using System.Collections.Generic;
using Utilities;

namespace GrCis.Rendering.Tests.Utilities;

/// <summary>GrCis's string helpers: counting, substitution, ids, splitting, sizes.</summary>
public class UtilStringsTests
{
  [Theory]
  [InlineData("a/b c:d?.txt", "abcd.txt")]
  [InlineData("<|>", "_")]
  [InlineData("scene_01", "scene_01")]
  public void FileNameString_drops_characters_a_file_name_cannot_hold(string text, string expected) =>
    Assert.Equal(expected, Util.FileNameString(text));

  [Theory]
  [InlineData("a\r\nb\nc", 2)]
  [InlineData("a\n\n", 2)]
  [InlineData("\r\n\r\n", 2)]
  [InlineData("\r\r\n", 2)]
  [InlineData("\n\r", 1)]
  [InlineData("no line end", 0)]
  [InlineData(null, 0)]
  public void EolnsInString_counts_two_character_line_ends_once(string? text, int expected) =>
    Assert.Equal(expected, Util.EolnsInString(text));

  [Fact]
  public void CharsInString_counts_one_character()
  {
    Assert.Equal(3, Util.CharsInString("a,b,c,", ','));
    Assert.Equal(0, Util.CharsInString(null, ','));
  }

  [Fact]
  public void Substitute_replaces_every_tag_and_stores_back_through_ref()
  {
    string page = "<p><%name></p><i><%name></i><%other>";
    Assert.Equal("<p>x</p><i>x</i><%other>", Util.Substitute(page, "name", "x"));
    Assert.Equal("<p></p><i></i><%other>", Util.Substitute(page, "name", null));
    Util.SubstituteFormat(ref page, "other", "{0:f2}", 1.5);
    Assert.Equal("<p><%name></p><i><%name></i>1.50", page);
    // An absent tag leaves the text alone without formatting (the arguments do not fit the format).
    Assert.Equal(page, Util.SubstituteFormat(page, "missing", "{3}", 1));
  }

  [Theory]
  [InlineData("192.168.0.1", true)]
  [InlineData("1.2.3.4", true)]
  [InlineData("1.2.3", false)]
  [InlineData("1.2..4", false)]
  [InlineData("1.2.3.4.", false)]
  [InlineData("a.2.3.4", false)]
  public void IsIpAddress_wants_four_digit_groups(string ip, bool expected) =>
    Assert.Equal(expected, Util.IsIpAddress(ip));

  [Theory]
  [InlineData("42", true)]
  [InlineData("-7", true)]
  [InlineData("4x", false)]
  [InlineData(null, false)]
  public void IsId_accepts_integers(string? id, bool expected) => Assert.Equal(expected, Util.IsId(id));

  [Theory]
  [InlineData("123abc", "123")]
  [InlineData("abc", "")]
  [InlineData("2024", "2024")]
  public void NumberPrefix_keeps_leading_digits(string text, string expected) =>
    Assert.Equal(expected, Util.NumberPrefix(text));

  [Fact]
  public void RemoveDiacritics_strips_combining_marks()
  {
    Assert.Equal("Prilis zlutoucky kun", Util.RemoveDiacritics("Příliš žluťoučký kůň"));
    Assert.Equal("", Util.RemoveDiacritics(null));
  }

  [Fact]
  public void KeyComparer_puts_numbers_first_by_value_and_dash_last()
  {
    var keys = new List<string> { "-", "beta", "10", "alpha", "9" };
    keys.Sort(Util.KeyComparer);
    Assert.Equal(new[] { "9", "10", "alpha", "beta", "-" }, keys);
  }

  [Theory]
  [InlineData("a|b||c", 0, new[] { "a", "b", "", "c" })]
  [InlineData(@"a\|b|c", 0, new[] { "a|b", "c" })]
  [InlineData(@"a\||b", 0, new[] { "a|", "b" })]
  [InlineData("x|y", 2, new[] { "y" })]
  [InlineData("xy", 2, new[] { "" })]
  public void BarSplit_splits_on_unescaped_bars(string text, int start, string[] expected) =>
    Assert.Equal(expected, Util.BarSplit(text, start));

  [Fact]
  public void BarSplit_past_the_end_is_null() => Assert.Null(Util.BarSplit("ab", 3));

  [Theory]
  [InlineData(8191L, "8191")]
  [InlineData(8192L, "8K")]
  [InlineData(8192L * 1024, "8M")]
  [InlineData(3L << 40, "3072G")]
  [InlineData(8192L << 30, "8T")]
  public void kmg_rounds_down_to_binary_units(long n, string expected) => Assert.Equal(expected, Util.kmg(n));

  [Fact]
  public void String_sizes_and_statistics_tell_interned_strings_apart()
  {
    string fresh = new string('q', 5) + "unlikely-to-be-interned";
    Assert.Equal(4, Util.OccupiedString(null));
    Assert.Equal(4, Util.OccupiedString("literal"));
    Assert.Equal((14 + 2 * fresh.Length + 3) & -4, Util.OccupiedString(fresh));
    Assert.Equal(8 + Util.OccupiedString(fresh), Util.OccupiedStrings(new[] { "literal", fresh, null }));

    long[] stat = new long[4];
    Util.StringStat(new[] { "literal", fresh }, stat);
    Assert.Equal(new long[] { 2, 7 + fresh.Length, 1, 7 }, stat);
  }

  [Fact]
  public void Interning_helpers_return_the_pooled_instances()
  {
    string built = new string('z', 3) + "-interned-key";
    List<string> pooled = Util.ListStringInterned(new[] { built })!;
    Assert.Same(string.IsInterned(built), pooled[0]);
    Assert.Same(pooled[0], Util.EmptyNullIntern(built));
    Assert.Null(Util.EmptyNullIntern(""));
    Assert.Null(Util.ListStringInterned(null));
  }
}
