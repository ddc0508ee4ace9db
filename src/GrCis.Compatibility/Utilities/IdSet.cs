using System;
using System.Collections.Generic;

namespace Utilities;

/// <summary>
/// A set of string ids that also holds id ranges (GrCis): <c>Add("obj12-obj40")</c> stores the range of ids
/// "obj12" to "obj40", <c>Add("100-")</c> every number from 100 up, <c>Add("-7")</c> every number up to 7.
/// Plain ids are kept as in a <see cref="HashSet{T}"/>.
/// </summary>
public class IdSet : HashSet<string>
{
  /// <summary>An id range: an optional common prefix followed by a number in [Min, Max].</summary>
  readonly record struct Range(string? Prefix, long Min, long Max)
  {
    /// <summary>"a-b" with a and b each an optional prefix and an optional number; null for no range at all.</summary>
    public static Range? Parse(string text)
    {
      string[] ends = text.Split('-');
      if (ends.Length != 2 || (ends[0].Length == 0 && ends[1].Length == 0))
        return null;
      int p0 = PrefixLength(ends[0]), p1 = PrefixLength(ends[1]);
      string? prefix = p0 == p1 && p0 > 0 && string.CompareOrdinal(ends[0], 0, ends[1], 0, p0) == 0 ? ends[0][..p0] : null;
      long min = long.TryParse(ends[0].AsSpan(p0), out long lo) ? lo : long.MinValue;
      long max = long.TryParse(ends[1].AsSpan(p1), out long hi) ? hi : long.MaxValue;
      var range = new Range(prefix, min, Math.Max(min, max));
      return range is { Prefix: null, Min: long.MinValue, Max: long.MaxValue } ? null : range;
    }

    /// <summary>Length of <paramref name="s"/> without its trailing digits.</summary>
    static int PrefixLength(string s)
    {
      int n = s.Length;
      while (n > 0 && char.IsDigit(s[n - 1]))
        n--;
      return n;
    }

    public bool Contains(string id)
    {
      ReadOnlySpan<char> number = id;
      if (Prefix != null)
      {
        if (!id.StartsWith(Prefix, StringComparison.Ordinal))
          return false;
        number = number[Prefix.Length..];
      }
      return long.TryParse(number, out long v) && v >= Min && v <= Max;
    }
  }

  readonly List<Range> ranges = new();

  public IdSet()
  {
  }

  /// <summary>The ids of <paramref name="collection"/>, taken as plain ids (as GrCis's constructor does).</summary>
  public IdSet(IEnumerable<string> collection) : base(collection)
  {
  }

  /// <summary>A copy of <paramref name="idset"/>, ranges included.</summary>
  public IdSet(IdSet idset)
  {
    if (idset == null)
      return;
    UnionWith(idset);
    ranges.AddRange(idset.ranges);
  }

  /// <summary>
  /// Adds an id, or a range when <paramref name="str"/> has a '-' (two characters at least). True when a new
  /// plain id was added, or the text names no range at all ("-"); false for an empty text, an id already
  /// present, and a range (ranges are not counted as set members, as in GrCis).
  /// </summary>
  public new bool Add(string str)
  {
    if (string.IsNullOrEmpty(str))
      return false;
    if (str.Length >= 2 && str.Contains('-'))
    {
      if (Range.Parse(str) is not Range range)
        return true;
      ranges.Add(range);
      return false;
    }
    return base.Add(str);
  }

  /// <summary>Plain ids plus ranges.</summary>
  public new int Count => base.Count + ranges.Count;

  public new void Clear()
  {
    base.Clear();
    ranges.Clear();
  }

  /// <summary>True for a plain id of the set or an id inside one of its ranges.</summary>
  public new bool Contains(string str)
  {
    if (base.Contains(str))
      return true;
    foreach (Range r in ranges)
      if (r.Contains(str))
        return true;
    return false;
  }
}
