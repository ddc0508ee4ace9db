using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Numerics;
using System.Text;

namespace Utilities;

/// <summary>
/// A histogram of integers in bins of <see cref="BinSize"/>: bin k holds [k·BinSize, (k+1)·BinSize) and is
/// labelled by its lower end. The common part of GrCis's <see cref="HistogramInt"/> and <see cref="HistogramLong"/>.
/// </summary>
public class BinnedHistogram<T> : Histogram<T> where T : IBinaryInteger<T>
{
  public T BinSize { get; set; }

  public BinnedHistogram(T binSize) => BinSize = binSize;

  /// <summary>Counts <paramref name="key"/> in its bin; returns the bin's new count.</summary>
  public new long Inc(T key) => base.Inc(BinOf(key));

  /// <summary>Index of the bin holding <paramref name="key"/>, rounded down also below zero (-1 is in bin -1, not 0).</summary>
  public T BinOf(T key)
  {
    T q = key / BinSize;
    return !T.IsZero(key % BinSize) && T.IsNegative(key) != T.IsNegative(BinSize) ? q - T.One : q;
  }

  /// <summary>The lower end of bin <paramref name="key"/>.</summary>
  public new string DefaultLabel(T key) => (key * BinSize).ToString(null, CultureInfo.InvariantCulture);

  /// <summary>The base table, bins labelled by their lower ends unless <paramref name="label"/> says otherwise.</summary>
  public new void Print(StringBuilder sb, int limit = 0, bool percent = false, bool perCum = false,
                        IComparer<T>? comp = null, BinLabel? label = null, Description? descr = null) =>
    base.Print(sb, limit, percent, perCum, comp, label ?? DefaultLabel, descr);

  public new void Print(TextWriter o, int limit = 0, bool percent = false, bool perCum = false,
                        IComparer<T>? comp = null, BinLabel? label = null, Description? descr = null) =>
    base.Print(o, limit, percent, perCum, comp, label ?? DefaultLabel, descr);

  public new void PrintHtml(StringBuilder sb, int limit = 0, bool percent = false, bool perCum = false,
                            IComparer<T>? comp = null, BinLabel? label = null, Description? descr = null) =>
    base.PrintHtml(sb, limit, percent, perCum, comp, label ?? DefaultLabel, descr);
}
