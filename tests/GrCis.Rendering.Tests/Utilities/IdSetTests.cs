using Utilities;

namespace GrCis.Rendering.Tests.Utilities;

/// <summary>GrCis's id sets: plain ids plus ranges of numbered ids (with or without a common prefix).</summary>
public class IdSetTests
{
  static IdSet Of(params string[] items)
  {
    var set = new IdSet();
    foreach (string item in items)
      set.Add(item);
    return set;
  }

  [Fact]
  public void Plain_ids_and_ranges_with_and_without_a_prefix()
  {
    IdSet ids = Of();
    Assert.True(ids.Add("sphere"));
    Assert.False(ids.Add("sphere"));
    Assert.False(ids.Add("obj12-obj40"));   // a range is stored, not counted as a new member
    Assert.False(ids.Add("100-"));
    Assert.False(ids.Add("-7"));
    Assert.False(ids.Add(""));
    Assert.True(ids.Add("-"));              // one character: a plain id

    Assert.Equal(5, ids.Count);             // "sphere", "-" and three ranges
    Assert.True(ids.Contains("sphere"));
    Assert.True(ids.Contains("obj12") && ids.Contains("obj40") && ids.Contains("obj25"));
    Assert.False(ids.Contains("obj41") || ids.Contains("obj11") || ids.Contains("box20"));
    Assert.True(ids.Contains("100") && ids.Contains("123456789"));
    Assert.True(ids.Contains("-3") && ids.Contains("7"));
    Assert.False(ids.Contains("8"));
    Assert.False(ids.Contains("50"));

    ids.Clear();
    Assert.Equal(0, ids.Count);
    Assert.False(ids.Contains("obj20"));
  }

  [Fact]
  public void A_reversed_range_holds_its_lower_end_and_a_copy_keeps_the_ranges()
  {
    IdSet ids = Of("x9-x3");
    Assert.True(ids.Contains("x9"));
    Assert.False(ids.Contains("x5"));

    var copy = new IdSet(ids);
    copy.Add("a");
    Assert.True(copy.Contains("x9"));
    Assert.Equal(2, copy.Count);
    Assert.Equal(1, ids.Count);
    Assert.True(new IdSet(new[] { "1-3" }).Contains("1-3"));   // the collection constructor takes plain ids
  }
}
