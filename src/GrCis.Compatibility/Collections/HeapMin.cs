using System;
using System.Collections.Generic;

namespace MathSupport;

/// <summary>GrCis's binary min-heap of comparable items: add, look at or remove the smallest.</summary>
public class HeapMin<T> where T : IComparable<T>
{
  protected List<T> arr = new();

  public HeapMin()
  {
  }

  public HeapMin(ICollection<T> c)
  {
    foreach (T item in c)
      Add(item);
  }

  public int Count => arr.Count;

  public void Add(T i)
  {
    arr.Add(i);
    CheckUp(arr.Count - 1);
  }

  /// <summary>The smallest item (default when empty).</summary>
  public T? GetMin() => arr.Count > 0 ? arr[0] : default;

  /// <summary>Removes and returns the smallest item (default when empty).</summary>
  public T? RemoveMin()
  {
    if (arr.Count == 0)
      return default;
    T min = arr[0];
    arr[0] = arr[^1];
    arr.RemoveAt(arr.Count - 1);
    CheckDown(0);
    return min;
  }

  protected void Swap(int i, int j) => (arr[i], arr[j]) = (arr[j], arr[i]);

  protected void CheckDown(int i) => HeapOrder.Down(arr, i, Compare);

  protected void CheckUp(int i) => HeapOrder.Up(arr, i, Compare);

  static int Compare(T a, T b) => a.CompareTo(b);
}
