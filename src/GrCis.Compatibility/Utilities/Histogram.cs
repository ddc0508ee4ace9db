using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;

namespace Utilities;

/// <summary>
/// Counts of equal values (GrCis): one counter per distinct key, plus <see cref="Other"/> for counts taken out
/// by <see cref="LimitValues"/>. Prints as a text or HTML table sorted by frequency or by key.
/// </summary>
public class Histogram<T> : Dictionary<T, MutableLong> where T : notnull
{
  /// <summary>Label of a bin in a printed table.</summary>
  public delegate string BinLabel(T key);

  /// <summary>Optional text at the end of a bin's printed line.</summary>
  public delegate string Description(T key);

  /// <summary>Sum of the bins removed by <see cref="LimitValues"/> or <see cref="LimitItems"/>; part of <see cref="Total"/>.</summary>
  public long Other { get; set; }

  /// <summary>Removes all bins and clears <see cref="Other"/>.</summary>
  public new void Clear()
  {
    base.Clear();
    Other = 0L;
  }

  /// <summary>Counts one more <paramref name="key"/>; returns its new count.</summary>
  public long Inc(T key) => Inc(key, 1L);

  /// <summary>Adds <paramref name="val"/> to the count of <paramref name="key"/>; returns its new count.</summary>
  public long Inc(T key, long val)
  {
    if (!TryGetValue(key, out MutableLong? count))
      Add(key, count = new MutableLong());
    return count.Inc(val);
  }

  /// <summary>Adds every bin of <paramref name="h"/> (null: nothing).</summary>
  public void Add(Histogram<T>? h)
  {
    if (h != null)
      foreach (KeyValuePair<T, MutableLong> bin in h)
        Inc(bin.Key, bin.Value.value);
  }

  /// <summary>Count of <paramref name="key"/> (0 when never counted).</summary>
  public long Freq(T key) => TryGetValue(key, out MutableLong? count) ? count.value : 0L;

  /// <summary>The key as invariant text.</summary>
  public static string DefaultLabel(T key) => Convert.ToString(key, CultureInfo.InvariantCulture) ?? "";

  /// <summary>Keys by descending count (ties in insertion order), without bins below <paramref name="lowerLimit"/> × <see cref="Total"/>.</summary>
  public List<T> KeySet(double lowerLimit = 0.0)
  {
    long limit = lowerLimit <= 0.0 ? 0L : (long)(Total() * lowerLimit);
    var keys = new List<T>();
    foreach (KeyValuePair<T, long> bin in Sorted(null))
      if (bin.Value >= limit)
        keys.Add(bin.Key);
    return keys;
  }

  /// <summary>Sets <paramref name="maxKey"/> to the most frequent key (the first such); false for an empty histogram.</summary>
  public bool Top(ref T maxKey)
  {
    bool found = false;
    long max = 0L;
    foreach (KeyValuePair<T, MutableLong> bin in this)
      if (!found || bin.Value.value > max)
      {
        (maxKey, max, found) = (bin.Key, bin.Value.value, true);
      }
    return found;
  }

  /// <summary>
  /// Merges the bins whose keys <paramref name="merge"/> compares as equal, then renames each bin to its
  /// <see cref="IAggregator{T}.ReduceKey"/> (bins meeting under one name are added together).
  /// </summary>
  public void Aggregate(IAggregator<T> merge)
  {
    var groups = new List<KeyValuePair<T, long>>();
    foreach (KeyValuePair<T, MutableLong> bin in this)
    {
      int g = groups.FindIndex(x => merge.Compare(x.Key, bin.Key) == 0);
      if (g < 0)
        groups.Add(new(bin.Key, bin.Value.value));
      else
        groups[g] = new(groups[g].Key, groups[g].Value + bin.Value.value);
    }
    base.Clear();
    foreach (KeyValuePair<T, long> group in groups)
      Inc(merge.ReduceKey(group.Key), group.Value);
  }

  /// <summary>Moves every bin with a count below <paramref name="limit"/> into <see cref="Other"/>; returns <see cref="Other"/>.</summary>
  public long LimitValues(long limit)
  {
    var small = new List<T>();
    foreach (KeyValuePair<T, MutableLong> bin in this)
      if (bin.Value.value < limit)
      {
        small.Add(bin.Key);
        Other += bin.Value.value;
      }
    foreach (T key in small)
      Remove(key);
    return Other;
  }

  /// <summary>
  /// Keeps the <paramref name="max"/> most frequent bins (and any tied with the last of them), moving the rest
  /// into <see cref="Other"/>; returns <see cref="Other"/>, or 0 when nothing had to go.
  /// </summary>
  public long LimitItems(int max)
  {
    if (max < 1 || max >= Count)
      return 0L;
    var counts = new List<long>(Count);
    foreach (MutableLong c in Values)
      counts.Add(c.value);
    counts.Sort(new ReverseComparer<long>());
    return LimitValues(counts[max - 1]);
  }

  /// <summary>Adds the count of <paramref name="from"/> (if any) to <paramref name="to"/> and removes <paramref name="from"/>.</summary>
  public void SubstituteKey(T from, T to)
  {
    if (!TryGetValue(from, out MutableLong? count) || EqualityComparer<T>.Default.Equals(from, to))
      return;
    Remove(from);
    Inc(to, count.value);
  }

  /// <summary>Sum of all bins and <see cref="Other"/>.</summary>
  public long Total()
  {
    long sum = Other;
    foreach (MutableLong c in Values)
      sum += c.value;
    return sum;
  }

  /// <summary>
  /// Appends a text table: label, count, optionally percent and cumulative percent of <see cref="Total"/>, and a
  /// description. Sorted by descending count, or by key with <paramref name="comp"/>. After <paramref name="limit"/>
  /// lines (0: no limit) the remaining bins are summed into a "Rest" line.
  /// </summary>
  public void Print(StringBuilder sb, int limit = 0, bool percent = false, bool perCum = false,
                    IComparer<T>? comp = null, BinLabel? label = null, Description? descr = null)
  {
    label ??= DefaultLabel;
    int width = 19;
    foreach (T key in Keys)
      width = Math.Max(width, label(key).Length);
    string row = "{0," + (width + 1) + "}: {1,10}";
    CultureInfo inv = CultureInfo.InvariantCulture;

    long rest = Rows(limit, comp, (key, count, share, cumulative) =>
    {
      sb.AppendFormat(inv, row, label(key), count);
      if (percent)
        sb.AppendFormat(inv, "{0,8:f2}%", share);
      if (perCum)
        sb.AppendFormat(inv, "{0,8:f2}%", cumulative);
      if (descr != null)
        sb.Append("  ").Append(descr(key));
      sb.AppendLine();
    });
    if (rest > 0L)
    {
      sb.AppendFormat(inv, row, "Rest", rest);
      if (percent)
        sb.AppendFormat(inv, "{0,8:f2}%", rest * 100.0 / Math.Max(1L, Total()));
      sb.AppendLine();
    }
  }

  /// <summary><see cref="Print(StringBuilder, int, bool, bool, IComparer{T}, BinLabel, Description)"/> written to <paramref name="o"/>.</summary>
  public void Print(TextWriter o, int limit = 0, bool percent = false, bool perCum = false,
                    IComparer<T>? comp = null, BinLabel? label = null, Description? descr = null)
  {
    var sb = new StringBuilder();
    Print(sb, limit, percent, perCum, comp, label, descr);
    o.Write(sb.ToString());
  }

  /// <summary>As <see cref="Print(StringBuilder, int, bool, bool, IComparer{T}, BinLabel, Description)"/>, as HTML table rows (<c>&lt;tr&gt;</c>, class "r" for right-aligned cells).</summary>
  public void PrintHtml(StringBuilder sb, int limit = 0, bool percent = false, bool perCum = false,
                        IComparer<T>? comp = null, BinLabel? label = null, Description? descr = null)
  {
    label ??= DefaultLabel;
    CultureInfo inv = CultureInfo.InvariantCulture;
    long rest = Rows(limit, comp, (key, count, share, cumulative) =>
    {
      sb.AppendFormat(inv, " <tr><td class=\"r\">{0}</td><td class=\"r\">{1}</td>", label(key), count);
      if (percent)
        sb.AppendFormat(inv, "<td class=\"r\">{0:f2}%</td>", share);
      if (perCum)
        sb.AppendFormat(inv, "<td class=\"r\">{0:f2}%</td>", cumulative);
      if (descr != null)
        sb.Append("<td>").Append(descr(key)).Append("</td>");
      sb.Append("</tr>\r\n");
    });
    if (rest > 0L)
    {
      sb.AppendFormat(inv, " <tr><td class=\"r\"><b>Rest</b></td><td class=\"r\">{0}</td>", rest);
      if (percent)
        sb.AppendFormat(inv, "<td class=\"r\">{0:f2}%</td>", rest * 100.0 / Math.Max(1L, Total()));
      if (perCum)
        sb.Append("<td>&nbsp;</td>");
      if (descr != null)
        sb.Append("<td>&nbsp;</td>");
      sb.Append("</tr>\r\n");
    }
  }

  /// <summary>Bins by descending count (stable), or by key with <paramref name="comp"/>.</summary>
  List<KeyValuePair<T, long>> Sorted(IComparer<T>? comp)
  {
    IEnumerable<KeyValuePair<T, long>> bins = this.Select(b => new KeyValuePair<T, long>(b.Key, b.Value.value));
    return (comp == null ? bins.OrderByDescending(b => b.Value) : bins.OrderBy(b => b.Key, comp)).ToList();
  }

  /// <summary>Calls <paramref name="line"/> for the first <paramref name="limit"/> bins (0: all) with percentages; returns the sum of the others.</summary>
  long Rows(int limit, IComparer<T>? comp, Action<T, long, double, double> line)
  {
    double toPercent = 100.0 / Math.Max(1L, Total());
    long soFar = 0L, rest = 0L;
    int printed = 0;
    foreach (KeyValuePair<T, long> bin in Sorted(comp))
    {
      soFar += bin.Value;
      if (limit > 0 && printed >= limit)
        rest += bin.Value;
      else
      {
        line(bin.Key, bin.Value, bin.Value * toPercent, soFar * toPercent);
        printed++;
      }
    }
    return rest;
  }
}
