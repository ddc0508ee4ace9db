using System;
using System.Collections.Generic;
using System.IO;
using System.Text;
using Utilities;

namespace GrCis.Rendering.Tests.Utilities;

/// <summary>GrCis's histograms: counting, limiting, merging and printed tables.</summary>
public class HistogramTests
{
  /// <summary>a: 5, b: 3, c: 3, d: 1 (counted in that order).</summary>
  static Histogram<string> Letters()
  {
    var h = new Histogram<string>();
    foreach (char c in "aaaaabbbcccd")
      h.Inc(c.ToString());
    return h;
  }

  [Fact]
  public void Counts_frequencies_and_totals()
  {
    Histogram<string> h = Letters();
    Assert.Equal(6, h.Inc("b", 3));
    Assert.Equal(5, h.Freq("a"));
    Assert.Equal(0, h.Freq("z"));
    Assert.Equal(15, h.Total());
    h.Add(Letters());
    Assert.Equal(9, h.Freq("b"));
    Assert.Equal(27, h.Total());
    h.Clear();
    Assert.Equal(0, h.Total());
  }

  [Fact]
  public void KeySet_is_by_descending_count_and_drops_rare_bins()
  {
    Histogram<string> h = Letters();
    Assert.Equal(new[] { "a", "b", "c", "d" }, h.KeySet());
    Assert.Equal(new[] { "a", "b", "c" }, h.KeySet(0.2));   // 12 × 0.2 = 2.4: d (1) goes
    string top = "";
    Assert.True(h.Top(ref top));
    Assert.Equal("a", top);
    Assert.False(new Histogram<string>().Top(ref top));
  }

  [Fact]
  public void Top_of_zero_counts_still_names_a_key()
  {
    var h = new Histogram<int>();
    h.Inc(7, 0);
    int top = -1;
    Assert.True(h.Top(ref top));
    Assert.Equal(7, top);
  }

  [Theory]
  [InlineData(3, 1, 11)]
  [InlineData(5, 7, 5)]
  [InlineData(1, 0, 12)]
  public void LimitValues_moves_small_bins_to_Other_and_keeps_the_total(long limit, long other, long kept)
  {
    Histogram<string> h = Letters();
    Assert.Equal(other, h.LimitValues(limit));
    Assert.Equal(other, h.Other);
    Assert.Equal(12, h.Total());
    long sum = 0;
    foreach (MutableLong c in h.Values)
      sum += c.value;
    Assert.Equal(kept, sum);
  }

  [Fact]
  public void Repeated_limits_accumulate_in_Other()
  {
    Histogram<string> h = Letters();
    h.LimitValues(2);
    Assert.Equal(7, h.LimitValues(4));   // d (1) before, b and c (3 each) now
    Assert.Equal(12, h.Total());
    Assert.Equal(new[] { "a" }, h.KeySet());
  }

  [Fact]
  public void LimitItems_keeps_the_most_frequent_and_their_ties()
  {
    Histogram<string> h = Letters();
    Assert.Equal(1, h.LimitItems(2));     // b and c tie for second place: both stay
    Assert.Equal(3, h.Count);
    Assert.Equal(0, h.LimitItems(5));
  }

  [Fact]
  public void Aggregate_merges_keys_of_one_group_under_the_reduced_key()
  {
    var h = new Histogram<string>();
    h.Inc("Sphere(1)", 2);
    h.Inc("Cube", 1);
    h.Inc("Sphere(2)", 3);
    h.Inc("Sphere", 4);
    h.Inc("Cube(9)", 5);
    h.Aggregate(new StringAggregatorFirstChar());
    Assert.Equal(2, h.Count);
    Assert.Equal(9, h.Freq("Sphere"));
    Assert.Equal(6, h.Freq("Cube"));
  }

  [Fact]
  public void SubstituteKey_moves_a_count()
  {
    Histogram<string> h = Letters();
    h.SubstituteKey("d", "a");
    h.SubstituteKey("missing", "a");
    h.SubstituteKey("b", "b");
    Assert.Equal(6, h.Freq("a"));
    Assert.False(h.ContainsKey("d"));
    Assert.Equal(3, h.Freq("b"));
  }

  [Fact]
  public void Print_aligns_columns_and_sums_the_rest()
  {
    var sb = new StringBuilder();
    Letters().Print(sb, limit: 2, percent: true, perCum: true, descr: k => k.ToUpperInvariant());
    string[] lines = sb.ToString().Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries);
    Assert.Equal(new[]
    {
      "                   a:          5   41.67%   41.67%  A",
      "                   b:          3   25.00%   66.67%  B",
      "                Rest:          4   33.33%",
    }, lines);
  }

  [Fact]
  public void Print_by_key_uses_the_comparer_and_wide_labels_widen_the_column()
  {
    var h = new Histogram<int>();
    h.Inc(2);
    h.Inc(10);
    h.Inc(10);
    var o = new StringWriter();
    h.Print(o, comp: Comparer<int>.Default, label: k => "bin number " + k + " of the table");
    string[] lines = o.ToString().Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries);
    Assert.Equal("  bin number 2 of the table:          1", lines[0]);   // one column wider than the widest label
    Assert.Equal(" bin number 10 of the table:          2", lines[1]);
  }

  [Fact]
  public void PrintHtml_writes_table_rows()
  {
    var sb = new StringBuilder();
    Letters().PrintHtml(sb, limit: 3, percent: true, perCum: true, descr: k => "x");
    string[] rows = sb.ToString().Split("\r\n", StringSplitOptions.RemoveEmptyEntries);
    Assert.Equal(4, rows.Length);
    Assert.Equal(" <tr><td class=\"r\">a</td><td class=\"r\">5</td><td class=\"r\">41.67%</td><td class=\"r\">41.67%</td><td>x</td></tr>", rows[0]);
    Assert.Equal(" <tr><td class=\"r\"><b>Rest</b></td><td class=\"r\">1</td><td class=\"r\">8.33%</td><td>&nbsp;</td><td>&nbsp;</td></tr>", rows[3]);
  }

  [Theory]
  [InlineData(10, new[] { 0, 9, 10, 25, -1, -10, -11 }, new[] { 0, 1, 2, -1, -2 }, new long[] { 2, 1, 1, 2, 1 })]
  [InlineData(1, new[] { 3, 3, -3 }, new[] { 3, -3 }, new long[] { 2, 1 })]
  public void HistogramInt_rounds_keys_down_to_their_bins(int size, int[] keys, int[] bins, long[] counts)
  {
    var h = new HistogramInt(size);
    foreach (int k in keys)
      h.Inc(k);
    Assert.Equal(bins.Length, h.Count);
    for (int i = 0; i < bins.Length; i++)
      Assert.Equal(counts[i], h.Freq(bins[i]));
  }

  [Fact]
  public void Binned_histograms_label_bins_by_their_lower_ends()
  {
    var h = new HistogramLong(1000L);
    h.Inc(1500L);
    h.Inc(1999L);
    h.Inc(-1L);
    Assert.Equal(1000L, h.BinSize);
    Assert.Equal("-1000", h.DefaultLabel(-1L));
    var o = new StringWriter();
    h.Print(o);
    Assert.StartsWith("                1000:          2", o.ToString());
    var sb = new StringBuilder();
    new HistogramInt(5) { BinSize = 5 }.PrintHtml(sb);
    Assert.Equal("", sb.ToString());
  }

  [Fact]
  public void Histogram2D_counts_pairs_by_secondary_then_primary_key()
  {
    var h = new Histogram2D<string, int>();
    h.Inc("red", 1);
    h.Inc("red", 1, 4);
    h.Inc("blue", 2);
    h.Inc(null!, 2);
    h.Add(Letters(), 3);
    Assert.Equal(5, h.Freq("red", 1));
    Assert.Equal(0, h.Freq("red", 2));
    Assert.Equal(3, h.Freq("b", 3));
    Assert.Equal(3, h.Count);
    Assert.Equal(18, h.Total());
  }
}
