using System;
using System.Collections.Generic;

namespace Utilities;

/// <summary>Orders values from the largest down (GrCis): <c>list.Sort(new ReverseComparer&lt;double&gt;())</c>.</summary>
public sealed class ReverseComparer<T> : IComparer<T> where T : IComparable<T>
{
  /// <summary>The reverse of <c>x.CompareTo(y)</c>; a null sorts after every value, as the mirror of the usual nulls-first order.</summary>
  public int Compare(T? x, T? y)
  {
    if (x is null)
      return y is null ? 0 : 1;
    if (y is null)
      return -1;
    return y.CompareTo(x);
  }
}
