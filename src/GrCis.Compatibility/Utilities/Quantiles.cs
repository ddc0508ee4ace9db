using System;
using System.Collections.Generic;
using System.Globalization;

namespace Utilities;

/// <summary>
/// Statistics of a list of numbers (GrCis): mean and variance always, and with the values kept
/// (<c>quantiles: true</c>) also quantiles (min, median, quartiles, max). Every list operation GrCis
/// overrides keeps the statistics up to date.
/// </summary>
public class Quantiles<T> : List<T>
{
  /// <summary>Whether the values are kept (needed for quantiles).</summary>
  protected bool storeValues;

  /// <summary>Number of values; equal to <c>Count</c> when they are kept.</summary>
  protected int N;

  /// <summary>Sum of the values.</summary>
  protected double Sx;

  /// <summary>Sum of the squares of the values.</summary>
  protected double Sxx;

  /// <summary>Whether the list has changed since it was last sorted.</summary>
  protected bool dirty;

  /// <param name="quantiles">Keep the values so that quantiles can be computed; false: mean and variance only.</param>
  /// <param name="capacity">Initial capacity of the list.</param>
  public Quantiles(bool quantiles = true, int capacity = 0) : base(quantiles ? Math.Max(capacity, 0) : 0)
  {
    storeValues = quantiles;
  }

  public new void Clear()
  {
    base.Clear();
    N = 0;
    Sx = Sxx = 0.0;
    dirty = false;
  }

  protected void AddStat(T x)
  {
    double v = Convert.ToDouble(x, CultureInfo.InvariantCulture);
    N++;
    Sx += v;
    Sxx += v * v;
    dirty = true;
  }

  protected void RemoveStat(T x)
  {
    double v = Convert.ToDouble(x, CultureInfo.InvariantCulture);
    N--;
    Sx -= v;
    Sxx -= v * v;
    dirty = true;
  }

  /// <summary>Arithmetic mean; NaN without values.</summary>
  public double Mean => N > 0 ? Sx / N : double.NaN;

  /// <summary>Variance of the values as the whole population (divided by N); NaN without values.</summary>
  public double Variance => N > 0 ? SumOfSquaredDeviations() / N : double.NaN;

  /// <summary>Variance of the values as a sample of a larger population (Bessel's correction, divided by N − 1); NaN for fewer than two values.</summary>
  public double VarianceBessel => N > 1 ? SumOfSquaredDeviations() / (N - 1.0) : double.NaN;

  // Rounding may leave a tiny negative number where the true value is 0.
  double SumOfSquaredDeviations() => Math.Max(0.0, Sxx - Sx * Sx / N);

  /// <summary>
  /// The <paramref name="i"/>-th of <paramref name="q"/> quantiles (i = 0: min, i = q: max; q = 2: median, 4: quartiles),
  /// interpolated linearly between the two nearest sorted values. NaN without values or when the values are not kept.
  /// </summary>
  public double Quantile(int q, int i)
  {
    if (!storeValues || N <= 0)
      return double.NaN;
    if (dirty)
    {
      Sort();
      dirty = false;
    }
    if (N == 1 || i <= 0)
      return Value(0);
    if (i >= q)
      return Value(N - 1);
    double position = (N - 1.0) * i / q;
    int below = (int)Math.Floor(position);
    double t = position - below;
    return (1.0 - t) * Value(below) + t * Value(below + 1);
  }

  double Value(int index) => Convert.ToDouble(base[index], CultureInfo.InvariantCulture);

  public double Min => Quantile(1, 0);

  public double Max => Quantile(1, 1);

  public double Median => Quantile(2, 1);

  /// <summary>The <paramref name="i"/>-th quartile (0: min, 2: median, 4: max).</summary>
  public double Quartile(int i) => Quantile(4, i);

  /// <summary>The value at <paramref name="index"/>; setting it updates the statistics.</summary>
  public new T this[int index]
  {
    get => base[index];
    set
    {
      RemoveStat(base[index]);
      base[index] = value;
      AddStat(value);
    }
  }

  public new void Add(T x)
  {
    if (storeValues)
      base.Add(x);
    AddStat(x);
  }

  public new void AddRange(IEnumerable<T> collection)
  {
    foreach (T x in collection)
      Add(x);
  }

  public new void Insert(int index, T x)
  {
    if (storeValues)
      base.Insert(index, x);
    AddStat(x);
  }

  /// <summary>Inserts the values at <paramref name="index"/> (GrCis appended them).</summary>
  public new void InsertRange(int index, IEnumerable<T> collection)
  {
    foreach (T x in collection)
      Insert(storeValues ? index++ : index, x);
  }

  /// <summary>Removes one occurrence of <paramref name="x"/>; a value that is not there changes nothing when values are kept.</summary>
  public new void Remove(T x)
  {
    if (!storeValues || base.Remove(x))
      RemoveStat(x);
  }

  /// <summary>Removes the value at <paramref name="index"/>; nothing happens for an index out of range or when values are not kept.</summary>
  public new void RemoveAt(int index)
  {
    if (!storeValues || index < 0 || index >= Count)
      return;
    RemoveStat(base[index]);
    base.RemoveAt(index);
  }

  public new void RemoveRange(int start, int count)
  {
    while (count-- > 0)
      RemoveAt(start);
  }

  public new void RemoveAll(Predicate<T> match)
  {
    if (!storeValues)
      return;
    foreach (T x in this)
      if (match(x))
        RemoveStat(x);
    base.RemoveAll(match);
  }
}
