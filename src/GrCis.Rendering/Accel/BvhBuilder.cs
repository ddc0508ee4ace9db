using System;
using System.Buffers;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;
using System.Threading.Tasks;

namespace Rendering.Accel;

/// <summary>
/// The binned SAH build behind <see cref="Bvh"/>: the <see cref="BvhShape"/>'s bins on the centroids of each axis, the
/// cheapest bin plane of the three axes, a leaf where splitting costs more (within the shape's sizes; both costs count
/// items in the shape's blocks).
/// Fast because the items are copied once into build order (box and centroid side by side, moved by the partition),
/// one pass bins all three axes, a child's box is the union of its bins and its centroid box is gathered by the
/// partition: no node rescans its items. Subtrees of at least <see cref="ParallelItems"/> items are built in parallel.
/// Every decision depends on the items only, so the tree is the same whatever the thread count: a subtree over m
/// items owns 2m − 1 node slots (its own, the left child's share from the next slot, the right child's after it), and
/// a last depth-first pass packs the slots into the sequential recursion's layout.
/// </summary>
internal sealed partial class BvhBuilder
{
  /// <summary>Most bin planes per axis a shape may ask for (the scratch on the stack is sized by it).</summary>
  public const int MaxBins = 32;

  const double TraversalCost = 1.0;

  /// <summary>Below this many items a subtree is built on the thread that reached it (a task costs more than it saves).</summary>
  public const int ParallelItems = 4096;

  readonly Item[] items;
  readonly int[] ids;
  readonly BvhShape shape;
  readonly BvhNode[] slots;
  readonly bool parallel;

  BvhBuilder(Item[] items, int[] ids, BvhShape shape, BvhNode[] slots, bool parallel)
  {
    if (shape.Bins < 2 || shape.Bins > MaxBins || !BitOperations.IsPow2(shape.Block))
      throw new ArgumentOutOfRangeException(nameof(shape));
    this.items = items;
    this.ids = ids;
    this.shape = shape;
    this.slots = slots;
    this.parallel = parallel;
  }

  /// <summary>
  /// Builds over <paramref name="boxes"/>[ids[k]] split by <paramref name="centers"/>[ids[k]], reordering
  /// <paramref name="ids"/> into leaf order (at least one). <paramref name="threads"/>: 1 builds on the calling thread
  /// only, any other value lets large subtrees run on the thread pool (≤ 0: when there is more than one core); the
  /// result does not depend on it. Returns the packed nodes and the depth (the root is level 1).
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveOptimization)]   // runs once per mesh: optimised code from the first call
  public static BvhNode[] Build(Aabb[] boxes, OpenTK.Mathematics.Vector3d[] centers, int[] ids, BvhShape shape, int threads, out int depth)
  {
    int n = ids.Length;
    Item[] items = ArrayPool<Item>.Shared.Rent(n);
    BvhNode[] slots = ArrayPool<BvhNode>.Shared.Rent(2 * n - 1);
    try
    {
      bool plain = true;
      for (int k = 0; k < n; k++)
      {
        ref readonly Aabb b = ref boxes[ids[k]];
        OpenTK.Mathematics.Vector3d c = centers[ids[k]];
        ref Item item = ref items[k];
        item.Min = Vector256.Create(b.Min.X, b.Min.Y, b.Min.Z, 0.0);
        item.Max = Vector256.Create(b.Max.X, b.Max.Y, b.Max.Z, 0.0);
        item.Center = Vector256.Create(c.X, c.Y, c.Z, 0.0);
        plain &= Plain(item.Min) & Plain(item.Max) & Plain(item.Center);
      }
      int cores = threads > 0 ? threads : Environment.ProcessorCount;
      var builder = new BvhBuilder(items, ids, shape, slots, cores > 1 && n >= 2 * ParallelItems);
      depth = plain ? builder.Root<Native>(n) : builder.Root<Exact>(n);
      int used = 0;
      builder.Pack(0, ref used);
      return slots.AsSpan(0, used).ToArray();
    }
    finally
    {
      ArrayPool<Item>.Shared.Return(items);
      ArrayPool<BvhNode>.Shared.Return(slots);
    }
  }

  int Root<T>(int n) where T : struct, IBinning
  {
    Scan<T>(0, n, out Box bounds, out Box cbounds);
    return Node<T>(0, n, 0, 1, bounds, cbounds);
  }

  /// <summary>No NaN among the four lanes: the native arithmetic then gives IEEE's answers (<see cref="Native"/>).</summary>
  static bool Plain(Vector256<double> v) => Vector256.EqualsAll(v, v);

  /// <summary>Writes the node over items [start, end) to <paramref name="slot"/> and its subtree after it; returns the subtree's deepest level.</summary>
  [MethodImpl(MethodImplOptions.AggressiveOptimization)]
  int Node<T>(int start, int end, int slot, int level, Box bounds, Box cbounds) where T : struct, IBinning
  {
    int count = end - start;
    slots[slot] = Leaf(bounds, start, count);
    if (count <= shape.SmallLeaf)
      return level;

    Split split = BestSplit<T>(start, end, cbounds, out Box leftBounds, out Box rightBounds);
    double leafCost = shape.BlockCost * shape.Blocks(count);
    double parentArea = bounds.HalfArea;
    double splitCost = split.Axis >= 0 && parentArea > 0.0
      ? TraversalCost + shape.BlockCost * split.Cost / parentArea
      : double.PositiveInfinity;
    int mid;
    Box leftCentres = default, rightCentres = default;
    if (splitCost < leafCost || (count > shape.LargeLeaf && split.Axis >= 0))
      mid = Partition<T>(start, end, cbounds, split, out leftCentres, out rightCentres);
    else if (count > shape.LargeLeaf)
      mid = start;   // inseparable centres: halves in the current order (below)
    else
      return level;
    if (mid == start || mid == end)
    {
      mid = (start + end) / 2;
      Scan<T>(start, mid, out leftBounds, out leftCentres);
      Scan<T>(mid, end, out rightBounds, out rightCentres);
    }

    int rightSlot = slot + 2 * (mid - start);
    slots[slot].Index = rightSlot;
    slots[slot].Count = 0;
    slots[slot].Axis = split.Axis >= 0 ? split.Axis : 0;
    if (parallel && count >= ParallelItems)
      return Fork<T>(start, mid, end, slot, level, leftBounds, leftCentres, rightBounds, rightCentres);
    return Math.Max(Node<T>(start, mid, slot + 1, level + 1, leftBounds, leftCentres),
                    Node<T>(mid, end, rightSlot, level + 1, rightBounds, rightCentres));
  }

  /// <summary>Both children at once (a method of its own: the lambdas' closure is allocated only here, not per node).</summary>
  int Fork<T>(int start, int mid, int end, int slot, int level, Box leftBounds, Box leftCentres, Box rightBounds, Box rightCentres)
    where T : struct, IBinning
  {
    int leftDepth = 0, rightDepth = 0;
    Parallel.Invoke(
      () => leftDepth = Node<T>(start, mid, slot + 1, level + 1, leftBounds, leftCentres),
      () => rightDepth = Node<T>(mid, end, slot + 2 * (mid - start), level + 1, rightBounds, rightCentres));
    return Math.Max(leftDepth, rightDepth);
  }

  /// <summary>
  /// The cheapest of the bin planes on the three axes (SAH, unnormalised: each side's blocks times its half area), Axis
  /// −1 when none separates; the boxes of the items on either side of it.
  /// </summary>
  [SkipLocalsInit, MethodImpl(MethodImplOptions.AggressiveOptimization)]
  Split BestSplit<T>(int start, int end, in Box cbounds, out Box left, out Box right) where T : struct, IBinning
  {
    int bins = shape.Bins;
    Span<int> binCount = stackalloc int[3 * MaxBins].Slice(0, 3 * bins);
    Span<Box> binBox = stackalloc Box[3 * MaxBins].Slice(0, 3 * bins);
    Span<double> rightArea = stackalloc double[MaxBins];
    Span<int> rightCount = stackalloc int[MaxBins];
    binCount.Clear();
    binBox.Fill(Box.Empty);
    Vector256<double> last = Vector256.Create(bins - 1.0);
    // Blocks of n items, (n + block − 1) / block, by a shift: a division per plane would cost the build several per cent.
    int round = shape.Block - 1, shift = BitOperations.Log2((uint)shape.Block);

    // Axes without extent are binned into bin 0 (scale 0) and skipped below.
    Vector256<double> cmin = cbounds.Min, extent = cbounds.Max - cmin;
    Vector256<double> scale = Vector256.Create(
      extent.GetElement(0) > 0.0 ? bins / extent.GetElement(0) : 0.0,
      extent.GetElement(1) > 0.0 ? bins / extent.GetElement(1) : 0.0,
      extent.GetElement(2) > 0.0 ? bins / extent.GetElement(2) : 0.0, 0.0);
    Item[] all = items;
    ref int counts0 = ref MemoryMarshal.GetReference(binCount);
    ref Box boxes0 = ref MemoryMarshal.GetReference(binBox);
    for (int k = start; k < end; k++)
    {
      ref Item item = ref all[k];
      T.Bins((item.Center - cmin) * scale, last, out int bx, out int by, out int bz);
      // Bin numbers are in [0, bins) by construction: no bounds checks in the hottest loop of the build.
      Unsafe.Add(ref counts0, bx)++;
      Unsafe.Add(ref counts0, bins + by)++;
      Unsafe.Add(ref counts0, 2 * bins + bz)++;
      Unsafe.Add(ref boxes0, bx).Add<T>(item.Min, item.Max);
      Unsafe.Add(ref boxes0, bins + by).Add<T>(item.Min, item.Max);
      Unsafe.Add(ref boxes0, 2 * bins + bz).Add<T>(item.Min, item.Max);
    }

    var best = new Split(-1, 0, double.PositiveInfinity);
    for (int axis = 0; axis < 3; axis++)
    {
      if (!(extent.GetElement(axis) > 0.0))
        continue;
      Span<int> counts = binCount.Slice(axis * bins, bins);
      Span<Box> axisBins = binBox.Slice(axis * bins, bins);
      Box acc = Box.Empty;
      int n = 0;
      for (int b = bins - 1; b > 0; b--)
      {
        acc.Add<T>(axisBins[b].Min, axisBins[b].Max);
        n += counts[b];
        rightCount[b] = n;
        rightArea[b] = acc.HalfArea;
      }
      acc = Box.Empty;
      n = 0;
      for (int b = 1; b < bins; b++)
      {
        acc.Add<T>(axisBins[b - 1].Min, axisBins[b - 1].Max);
        n += counts[b - 1];
        if (n == 0 || rightCount[b] == 0)
          continue;
        double cost = ((n + round) >> shift) * acc.HalfArea + ((rightCount[b] + round) >> shift) * rightArea[b];
        if (cost < best.Cost)
          best = new Split(axis, b, cost);
      }
    }

    left = right = Box.Empty;
    if (best.Axis >= 0)
      for (int b = 0; b < bins; b++)
      {
        ref Box bin = ref binBox[best.Axis * bins + b];
        if (b < best.Bin)
          left.Add<T>(bin.Min, bin.Max);
        else
          right.Add<T>(bin.Min, bin.Max);
      }
    return best;
  }

  /// <summary>
  /// Items whose centre falls in a bin below the split plane first (the same swaps as always, so the same item order);
  /// returns the first of the rest, with the centroid box of each side.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveOptimization)]
  int Partition<T>(int start, int end, in Box cbounds, Split split, out Box leftCentres, out Box rightCentres) where T : struct, IBinning
  {
    int axis = split.Axis, bins = shape.Bins;
    double cmin = cbounds.Min.GetElement(axis), scale = bins / (cbounds.Max.GetElement(axis) - cmin);
    Item[] all = items;
    leftCentres = rightCentres = Box.Empty;
    int i = start, j = end - 1;
    while (i <= j)
    {
      Vector256<double> c = all[i].Center;
      if (Math.Min(bins - 1, (int)((c.GetElement(axis) - cmin) * scale)) < split.Bin)
      {
        leftCentres.Add<T>(c, c);
        i++;
      }
      else
      {
        (all[i], all[j]) = (all[j], all[i]);
        (ids[i], ids[j]) = (ids[j], ids[i]);
        rightCentres.Add<T>(c, c);
        j--;
      }
    }
    return i;
  }

  /// <summary>Box and centroid box of items [start, end).</summary>
  [MethodImpl(MethodImplOptions.AggressiveOptimization)]
  void Scan<T>(int start, int end, out Box bounds, out Box cbounds) where T : struct, IBinning
  {
    bounds = cbounds = Box.Empty;
    for (int k = start; k < end; k++)
    {
      ref Item item = ref items[k];
      bounds.Add<T>(item.Min, item.Max);
      cbounds.Add<T>(item.Center, item.Center);
    }
  }

  /// <summary>
  /// Moves the subtree at <paramref name="slot"/> to depth-first positions from <paramref name="used"/> on, in place: a
  /// node's position never exceeds its slot, and slots only grow in depth-first order, so no unread node is overwritten.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveOptimization)]
  int Pack(int slot, ref int used)
  {
    int self = used++;
    BvhNode node = slots[slot];
    if (node.Count == 0)
    {
      Pack(slot + 1, ref used);
      node.Index = Pack(node.Index, ref used);
    }
    slots[self] = node;
    return self;
  }

  static BvhNode Leaf(in Box b, int first, int count) => new()
  {
    MinX = b.Min.GetElement(0), MinY = b.Min.GetElement(1), MinZ = b.Min.GetElement(2),
    MaxX = b.Max.GetElement(0), MaxY = b.Max.GetElement(1), MaxZ = b.Max.GetElement(2),
    Index = first,
    Count = count,
  };

  readonly record struct Split(int Axis, int Bin, double Cost);
}
