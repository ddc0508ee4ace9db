using System;
using System.Buffers;
using Rendering.Accel;

namespace Rendering;

/// <summary>
/// The mesh's eight-wide tree (<see cref="MeshNode"/>) from its binary SAH tree: which binary nodes become wide nodes
/// and which subtrees become one leaf lane, chosen for the least expected cost by dynamic programming over the binary
/// tree (the collapse of Ylitie, Karras and Laine, "Efficient Incoherent Ray Traversal on GPUs Through Compressed Wide
/// BVHs", 2017). A ray meets a box with probability proportional to its surface area; opening a wide node costs
/// <see cref="NodeCost"/> block tests, a leaf lane its blocks. Cost(n, i), the least cost of binary node n's subtree in
/// at most i lanes of its wide parent, is one lane (a leaf over all its items if there are at most
/// <see cref="BvhShape.LargeLeaf"/>, or a wide node whose eight lanes share n's two children) or k lanes for n's left
/// child and i − k for its right. The greedy collapse (open the largest inner child until there are eight) filled the
/// top of the tree and left the nodes below it half empty (4.4 lanes of 8 on the Buddha); this one puts the lanes
/// where the rays go. The lanes keep the binary tree's left-to-right order, so a leaf's items stay one range.
/// </summary>
internal sealed class MeshCollapse
{
  const int Width = MeshNode.Width;

  /// <summary>A wide node's visit in block tests (1, 1.5 and 2 alike within the spread on four meshes).</summary>
  public const double NodeCost = 1.0;

  readonly BvhNode[] b;
  readonly BvhShape shape;
  // Per binary node n and lane budget i (index n·8 + i − 1): the least cost, the lanes it really takes (1 or the
  // budget at which it was reached) and, for two or more lanes j, how many go to the left child.
  readonly double[] cost;
  readonly byte[] lanes, left;
  readonly bool[] asLeaf;      // one lane: a leaf over the subtree (else a wide node)
  readonly int[] first, items; // the subtree's items: a range of the tree's leaf order

  MeshCollapse(Bvh tree, BvhShape shape)
  {
    b = tree.Nodes;
    this.shape = shape;
    int m = b.Length;
    cost = ArrayPool<double>.Shared.Rent(m * Width);
    lanes = ArrayPool<byte>.Shared.Rent(m * Width);
    left = ArrayPool<byte>.Shared.Rent(m * Width);
    asLeaf = ArrayPool<bool>.Shared.Rent(m);
    first = ArrayPool<int>.Shared.Rent(m);
    items = ArrayPool<int>.Shared.Rent(m);
  }

  void Return()
  {
    ArrayPool<double>.Shared.Return(cost);
    ArrayPool<byte>.Shared.Return(lanes);
    ArrayPool<byte>.Shared.Return(left);
    ArrayPool<bool>.Shared.Return(asLeaf);
    ArrayPool<int>.Shared.Return(first);
    ArrayPool<int>.Shared.Return(items);
  }

  /// <summary>
  /// The eight-wide tree of <paramref name="tree"/> (built with <paramref name="shape"/>'s leaf limit and blocks). Leaf
  /// lanes get their first item and item count (the caller turns them into blocks). Boxes grown by
  /// <paramref name="pad"/>. <paramref name="stackSize"/>: traversal stack entries that can be live at once (each step
  /// pops one entry and pushes at most eight: seven more per level of this tree, whose depth is about a third of the
  /// binary tree's; sized by the binary depth, a stack would often be too large to live on the thread's stack).
  /// </summary>
  public static MeshNode[] Collapse(Bvh tree, BvhShape shape, double pad, out int stackSize)
  {
    stackSize = 2;
    if (tree.Items.Length == 0)
    {
      var none = new MeshNode[1];   // a tree over nothing: one node without lanes
      none[0].Clear();
      return none;
    }
    var collapse = new MeshCollapse(tree, shape);
    try
    {
      collapse.Costs();
      // Counted first, so the nodes are written straight into their final array (no list to grow and copy).
      int count = 0, depth = 0;
      collapse.Node(0, 1, null, pad, ref count, ref depth);
      var nodes = new MeshNode[count];
      count = 0;
      collapse.Node(0, 1, nodes, pad, ref count, ref depth);
      stackSize = (Width - 1) * depth + 2;
      return nodes;
    }
    finally
    {
      collapse.Return();
    }
  }

  /// <summary>Cost(n, i) for every node, children first (a child's number is above its parent's).</summary>
  void Costs()
  {
    Span<double> split = stackalloc double[Width + 1];
    for (int n = b.Length - 1; n >= 0; n--)
    {
      ref readonly BvhNode node = ref b[n];
      double area = HalfArea(node);
      int at = n * Width;
      if (node.Count > 0)
      {
        (first[n], items[n], asLeaf[n]) = (node.Index, node.Count, true);
        cost.AsSpan(at, Width).Fill(area * shape.Blocks(node.Count));
        lanes.AsSpan(at, Width).Fill(1);
        continue;
      }
      int l = (n + 1) * Width, r = node.Index * Width;
      (first[n], items[n]) = (first[n + 1], items[n + 1] + items[node.Index]);
      // The best share of j lanes between the children (ties: fewer to the left).
      for (int j = 2; j <= Width; j++)
      {
        split[j] = double.PositiveInfinity;
        for (int k = 1; k < j; k++)
        {
          double c = cost[l + k - 1] + cost[r + j - k - 1];
          if (c < split[j])
          {
            split[j] = c;
            left[at + j - 1] = (byte)k;
          }
        }
      }
      double leaf = items[n] <= shape.LargeLeaf ? area * shape.Blocks(items[n]) : double.PositiveInfinity;
      double wide = NodeCost * area + split[Width];
      asLeaf[n] = leaf <= wide;
      cost[at] = Math.Min(leaf, wide);
      lanes[at] = 1;
      for (int i = 2; i <= Width; i++)
      {
        bool more = split[i] < cost[at + i - 2];   // more lanes only where they lower the cost
        cost[at + i - 1] = more ? split[i] : cost[at + i - 2];
        lanes[at + i - 1] = more ? (byte)i : lanes[at + i - 2];
      }
    }
  }

  /// <summary>
  /// Adds the wide node over inner binary node <paramref name="binary"/> (or over the root leaf) at
  /// <paramref name="used"/>, its subtree after it; without an array, only counts. <paramref name="depth"/>: the deepest
  /// level reached (this node's is <paramref name="level"/>).
  /// </summary>
  int Node(int binary, int level, MeshNode[]? nodes, double pad, ref int used, ref int depth)
  {
    Span<int> picks = stackalloc int[Width];   // binary node per lane; ~n for a leaf over n's subtree
    int count = 0;
    if (b[binary].Count > 0)
      picks[count++] = ~binary;
    else
    {
      int k = left[binary * Width + Width - 1];
      Lanes(binary + 1, k, picks, ref count);
      Lanes(b[binary].Index, Width - k, picks, ref count);
    }

    int self = used++;
    depth = Math.Max(depth, level);
    if (nodes != null)
      nodes[self].Clear();
    for (int lane = 0; lane < count; lane++)
    {
      int pick = picks[lane];
      int n = pick >= 0 ? pick : ~pick;
      int index = pick >= 0 ? Node(n, level + 1, nodes, pad, ref used, ref depth) : first[n];
      if (nodes == null)
        continue;
      ref MeshNode node = ref nodes[self];
      node.SetBox(lane, b[n], pad);
      node.Index[lane] = index;
      node.Count[lane] = pick >= 0 ? 0 : items[n];
    }
    return self;
  }

  /// <summary>The lanes binary node <paramref name="n"/>'s subtree takes with a budget of <paramref name="budget"/>, appended.</summary>
  void Lanes(int n, int budget, Span<int> picks, ref int count)
  {
    int j = lanes[n * Width + budget - 1];
    if (j == 1)
    {
      picks[count++] = asLeaf[n] ? ~n : n;
      return;
    }
    int k = left[n * Width + j - 1];
    Lanes(n + 1, k, picks, ref count);
    Lanes(b[n].Index, j - k, picks, ref count);
  }

  static double HalfArea(in BvhNode n)
  {
    double x = n.MaxX - n.MinX, y = n.MaxY - n.MinY, z = n.MaxZ - n.MinZ;
    return x * y + y * z + z * x;
  }
}
