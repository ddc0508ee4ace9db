using System.Collections.Generic;

namespace Utilities;

/// <summary>
/// Counts of value pairs (GrCis): for each secondary key <typeparamref name="Tsec"/> a <see cref="Histogram{T}"/>
/// of primary keys <typeparamref name="Tpri"/>. Null keys are not counted.
/// </summary>
public class Histogram2D<Tpri, Tsec> : Dictionary<Tsec, Histogram<Tpri>> where Tpri : notnull where Tsec : notnull
{
  /// <summary>Counts one more pair; returns its new count (0 for a null key).</summary>
  public long Inc(Tpri key1, Tsec key2) => Inc(key1, key2, 1L);

  /// <summary>Adds <paramref name="count"/> to the pair; returns its new count (0 for a null key).</summary>
  public long Inc(Tpri key1, Tsec key2, long count) =>
    key1 is null || key2 is null ? 0L : Row(key2).Inc(key1, count);

  /// <summary>Adds every bin of <paramref name="h"/> to the row of <paramref name="key2"/>.</summary>
  public void Add(Histogram<Tpri>? h, Tsec key2)
  {
    if (key2 is not null)
      Row(key2).Add(h);
  }

  /// <summary>Count of the pair (0 when never counted).</summary>
  public long Freq(Tpri key1, Tsec key2) =>
    key1 is not null && key2 is not null && TryGetValue(key2, out Histogram<Tpri>? row) ? row.Freq(key1) : 0L;

  /// <summary>Sum of all counts.</summary>
  public long Total()
  {
    long sum = 0L;
    foreach (Histogram<Tpri> row in Values)
      sum += row.Total();
    return sum;
  }

  Histogram<Tpri> Row(Tsec key2)
  {
    if (!TryGetValue(key2, out Histogram<Tpri>? row))
      Add(key2, row = new Histogram<Tpri>());
    return row;
  }
}
