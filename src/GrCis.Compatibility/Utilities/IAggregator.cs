using System.Collections.Generic;

namespace Utilities;

/// <summary>
/// A comparer that first reduces each key to the group it belongs to (GrCis): keys with the same reduced key
/// compare equal, so a sorted dictionary or a histogram keyed by such a comparer aggregates them.
/// </summary>
public interface IAggregator<T> : IComparer<T>
{
  /// <summary>The group key of <paramref name="key"/>.</summary>
  T ReduceKey(T key);
}
