using System.Collections;
using System.Collections.Generic;

namespace MathSupport;

/// <summary>
/// GrCis's binary heap ordered by a comparer: the "top" is the item the comparer puts first
/// (e.g. the farthest of the k nearest neighbours, with a reversed distance comparer).
/// Enumerates in heap order; <see cref="Sort"/> re-establishes the order after items were changed.
/// </summary>
public class HeapTop<T> : IEnumerable<T>
{
  protected List<T> arr = new();

  IComparer<T>? comp;

  public HeapTop(IComparer<T>? co = null) => comp = co;

  public HeapTop(ICollection<T> c, IComparer<T>? co = null) : this(co)
  {
    foreach (T item in c)
      Add(item);
  }

  /// <summary>The order (the type's default order when none is set).</summary>
  public IComparer<T> Comp
  {
    get => comp ?? Comparer<T>.Default;
    set => comp = value;
  }

  public T this[int index]
  {
    get => arr[index];
    set => arr[index] = value;
  }

  public int Count => arr.Count;

  public IEnumerator<T> GetEnumerator() => arr.GetEnumerator();

  IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();

  public void Add(T t)
  {
    arr.Add(t);
    CheckUp(arr.Count - 1);
  }

  /// <summary>The top item (default when empty).</summary>
  public T? GetTop() => arr.Count > 0 ? arr[0] : default;

  /// <summary>Removes and returns the top item (default when empty).</summary>
  public T? RemoveTop()
  {
    if (arr.Count == 0)
      return default;
    T top = arr[0];
    arr[0] = arr[^1];
    arr.RemoveAt(arr.Count - 1);
    CheckDown(0);
    return top;
  }

  /// <summary>Replaces the top with <paramref name="t"/> and returns the old top (on an empty heap: adds, returns default).</summary>
  public T? SwapTop(T t)
  {
    if (arr.Count == 0)
    {
      Add(t);
      return default;
    }
    T top = arr[0];
    arr[0] = t;
    CheckDown(0);
    return top;
  }

  public void Clear() => arr.Clear();

  /// <summary>Rebuilds the heap order of all items.</summary>
  public void Sort()
  {
    for (int i = 1; i < arr.Count; i++)
      CheckUp(i);
  }

  protected void Swap(int i, int j) => (arr[i], arr[j]) = (arr[j], arr[i]);

  public void CheckDown(int i) => HeapOrder.Down(arr, i, Comp.Compare);

  protected void CheckUp(int i) => HeapOrder.Up(arr, i, Comp.Compare);
}
