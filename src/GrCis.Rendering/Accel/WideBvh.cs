using System;

namespace Rendering.Accel;

/// <summary>
/// A <see cref="Bvh"/> collapsed to four children per node (<see cref="WideNode"/>): one SIMD step tests four boxes,
/// and a ray visits about half as many nodes. Built from the binary tree by pulling up grandchildren: while a node has
/// fewer than four children, its inner child of largest surface area is replaced by that child's two children. The
/// leaves, and so <see cref="Items"/>, are the binary tree's. The scene traversal (<see cref="PreparedScene"/>) picks
/// the answer by T and then by item, not by visiting order, so the order of a node's lanes only affects speed. (A mesh's
/// tree is collapsed the same way to eight float boxes per node: <see cref="MeshNode"/>.)
/// </summary>
internal sealed class WideBvh
{
  public readonly WideNode[] Nodes;

  /// <summary>Item ids in leaf order (the binary tree's).</summary>
  public readonly int[] Items;

  /// <summary>The box around everything (the binary tree's root): one scalar test sends a ray that misses it all away early.</summary>
  public readonly BvhNode Root;

  /// <summary>Traversal stack entries that can be live at once (each step pops one and pushes at most four).</summary>
  public readonly int StackSize;

  WideBvh(WideNode[] nodes, BvhNode root, int[] items, int stackSize)
  {
    Nodes = nodes;
    Root = root;
    Items = items;
    StackSize = stackSize;
  }

  /// <summary>
  /// Collapses <paramref name="tree"/>. Every box is grown by <paramref name="pad"/>: a padded test may keep a box an
  /// exact one would drop, never the reverse, which is all exactness needs when the item tests decide.
  /// </summary>
  public static WideBvh Collapse(Bvh tree, double pad = 0.0)
  {
    WideNode[] nodes;
    if (tree.Items.Length == 0)
      nodes = new WideNode[1];   // a tree over nothing: one node without lanes
    else
    {
      // Counted first, so the nodes are written straight into their final array (no list to grow and copy).
      int count = 0;
      new Collapser(tree, pad, null).Node(0, ref count);
      nodes = new WideNode[count];
      count = 0;
      new Collapser(tree, pad, nodes).Node(0, ref count);
    }
    return new WideBvh(nodes, tree.Nodes[0], tree.Items, (WideNode.Width - 1) * tree.Depth + 2);
  }

  readonly struct Collapser(Bvh tree, double pad, WideNode[]? nodes)
  {
    /// <summary>
    /// Adds the wide node whose children are those of binary node <paramref name="binary"/> (or the node itself, a leaf
    /// root) at <paramref name="used"/>, its subtree after it; without an array, only counts.
    /// </summary>
    public int Node(int binary, ref int used)
    {
      BvhNode[] b = tree.Nodes;
      Span<int> picks = stackalloc int[WideNode.Width];
      int count = tree.WideChildren(binary, picks);

      int self = used++;
      if (nodes == null)
      {
        for (int lane = 0; lane < count; lane++)
          if (b[picks[lane]].Count == 0)
            Node(picks[lane], ref used);
        return self;
      }
      ref WideNode node = ref nodes[self];
      for (int lane = 0; lane < count; lane++)
      {
        ref BvhNode child = ref b[picks[lane]];
        node.SetBox(lane, child, pad);
        if (child.Count > 0)
        {
          node.Index[lane] = child.Index;
          node.Count[lane] = child.Count;
        }
        else
          node.Index[lane] = Node(picks[lane], ref used);
      }
      return self;
    }
  }
}
