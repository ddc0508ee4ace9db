using System;
using System.Collections.Generic;

namespace MathSupport;

/// <summary>Sift-up and sift-down of a binary heap kept in a list (smallest at index 0 by <c>compare</c>).</summary>
internal static class HeapOrder
{
  public static void Up<T>(List<T> a, int i, Comparison<T> compare)
  {
    while (i > 0)
    {
      int parent = (i - 1) / 2;
      if (compare(a[parent], a[i]) <= 0)
        return;
      (a[parent], a[i]) = (a[i], a[parent]);
      i = parent;
    }
  }

  public static void Down<T>(List<T> a, int i, Comparison<T> compare)
  {
    while (true)
    {
      int child = 2 * i + 1;
      if (child >= a.Count)
        return;
      if (child + 1 < a.Count && compare(a[child], a[child + 1]) > 0)
        child++;
      if (compare(a[i], a[child]) <= 0)
        return;
      (a[i], a[child]) = (a[child], a[i]);
      i = child;
    }
  }
}
