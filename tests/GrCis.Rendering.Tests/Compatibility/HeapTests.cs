using System.Collections.Generic;
using System.Linq;
using MathSupport;

namespace GrCis.Rendering.Tests.Compatibility;

/// <summary>GrCis's heaps: HeapMin gives items smallest first; HeapTop keeps the k best with SwapTop.</summary>
public class HeapTests
{
  [Fact]
  public void HeapMin_removes_in_ascending_order()
  {
    var rnd = new RandomJames(5);
    var values = Enumerable.Range(0, 200).Select(_ => rnd.RandomInteger(0, 50)).ToList();
    var heap = new HeapMin<int>(values);
    Assert.Equal(200, heap.Count);
    Assert.Equal(values.Min(), heap.GetMin());
    var drained = new List<int>();
    while (heap.Count > 0)
      drained.Add(heap.RemoveMin());
    Assert.Equal(values.Order(), drained);
    Assert.Equal(0, heap.RemoveMin());   // empty: default
  }

  [Fact]
  public void HeapTop_with_a_reversed_order_keeps_the_k_nearest()
  {
    double[] distances = { 5.0, 1.0, 9.0, 3.0, 7.0, 2.0, 8.0 };
    // Top = the farthest of the kept ones, so a nearer candidate replaces it.
    var best = new HeapTop<double>(Comparer<double>.Create((a, b) => b.CompareTo(a)));
    foreach (double d in distances)
      if (best.Count < 3)
        best.Add(d);
      else if (d < best.GetTop())
        best.SwapTop(d);
    Assert.Equal(new[] { 1.0, 2.0, 3.0 }, best.Order());
    Assert.Equal(3.0, best.GetTop());
    best[0] = 0.5;     // changed in place: Sort restores the heap
    best.Sort();
    Assert.Equal(2.0, best.RemoveTop());
    best.Clear();
    Assert.Equal(0.0, best.SwapTop(4.0));
    Assert.Single(best);
  }

  [Fact]
  public void Summed_area_tables_sum_any_rectangle()
  {
    var t = new SummedAreaTableLong(4, 3);
    var i = new SummedAreaTableInt(4, 3);
    for (int x = 0; x < 4; x++)
      for (int y = 0; y < 3; y++)
        i.table![x, y] = (int)(t.table![x, y] = x + 10 * y);
    t.ComputeTable();
    i.ComputeTable();
    // x 1..3, y 1..2: (1+2+3)·2 + 10·(1+2)·3 = 12 + 90
    Assert.Equal(102L, t.Sum(1, 3, 1, 2));
    Assert.Equal(102, i.Sum(1, 3, 1, 2));
    Assert.Equal(0L, t.Sum(0, 0, 0, 0));
    Assert.Equal(t.table![3, 2], t.Sum(0, 3, 0, 2));
    Assert.Throws<System.ArgumentOutOfRangeException>(() => t.Sum(2, 1, 0, 0));
  }
}
