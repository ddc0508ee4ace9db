using System;
using System.Collections.Generic;
using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>
/// Bounding volume hierarchy over boxes, built with binned SAH and stored as a flat node array
/// (depth-first, left child adjacent) so traversal is a loop over an index stack.
/// </summary>
internal sealed class Bvh
{
  const int Bins = 16;
  const int MaxLeaf = 4;

  // Relative costs of visiting a node and of testing an item (a transform chain and a solid).
  const double TraversalCost = 1.0;
  const double ItemCost = 2.0;

  public readonly BvhNode[] Nodes;

  /// <summary>Item ids in leaf order.</summary>
  public readonly int[] Items;

  /// <summary>Maximal depth (for sizing the traversal stack).</summary>
  public readonly int Depth;

  /// <summary>Per inner node, both children's boxes packed for the two-box SIMD test (unused for leaves).</summary>
  public readonly BvhChildBoxes[] Children;

  Bvh(BvhNode[] nodes, int[] items, int depth)
  {
    Nodes = nodes;
    Items = items;
    Depth = depth;
    Children = new BvhChildBoxes[nodes.Length];
    for (int i = 0; i < nodes.Length; i++)
      if (nodes[i].Count == 0)
        Children[i] = new BvhChildBoxes(nodes[i + 1], nodes[nodes[i].Index]);
  }

  /// <summary>Builds over <paramref name="boxes"/>[ids[k]]; ids are reordered into leaf order.</summary>
  public static Bvh Build(Aabb[] boxes, int[] ids)
  {
    var nodes = new List<BvhNode>(Math.Max(1, 2 * ids.Length));
    var centers = new Vector3d[boxes.Length];
    for (int i = 0; i < boxes.Length; i++)
      centers[i] = boxes[i].Center;
    int depth = 0;
    if (ids.Length > 0)
      BuildNode(boxes, centers, ids, 0, ids.Length, nodes, 1, ref depth);
    return new Bvh(nodes.ToArray(), ids, depth);
  }

  static int BuildNode(Aabb[] boxes, Vector3d[] centers, int[] ids, int start, int end, List<BvhNode> nodes, int level, ref int depth)
  {
    depth = Math.Max(depth, level);
    Aabb bounds = Aabb.Empty, cbounds = Aabb.Empty;
    for (int k = start; k < end; k++)
    {
      bounds.Add(boxes[ids[k]]);
      cbounds.Add(centers[ids[k]]);
    }

    int self = nodes.Count;
    nodes.Add(Leaf(bounds, start, end - start));
    int count = end - start;
    if (count <= 1)
      return self;

    // Split axis: the largest extent of the centroids.
    Vector3d ext = cbounds.Max - cbounds.Min;
    int axis = ext.X >= ext.Y && ext.X >= ext.Z ? 0 : ext.Y >= ext.Z ? 1 : 2;
    double cmin = cbounds.Min[axis], cext = ext[axis];
    int mid;
    if (cext <= 0.0)
    {
      if (count <= MaxLeaf)
        return self;
      mid = (start + end) / 2;
    }
    else
    {
      // Bin the centroids, then sweep for the cheapest plane.
      Span<int> binCount = stackalloc int[Bins];
      var binBox = new Aabb[Bins];
      for (int b = 0; b < Bins; b++)
        binBox[b] = Aabb.Empty;
      double scale = Bins / cext;
      for (int k = start; k < end; k++)
      {
        int b = Math.Min(Bins - 1, (int)((centers[ids[k]][axis] - cmin) * scale));
        binCount[b]++;
        binBox[b].Add(boxes[ids[k]]);
      }

      Span<double> leftArea = stackalloc double[Bins];
      Span<int> leftCount = stackalloc int[Bins];
      Aabb acc = Aabb.Empty;
      int n = 0;
      for (int b = 0; b < Bins - 1; b++)
      {
        acc.Add(binBox[b]);
        n += binCount[b];
        leftArea[b] = acc.HalfArea;
        leftCount[b] = n;
      }
      acc = Aabb.Empty;
      n = 0;
      double bestCost = double.PositiveInfinity;
      int bestSplit = -1;
      for (int b = Bins - 1; b > 0; b--)
      {
        acc.Add(binBox[b]);
        n += binCount[b];
        if (leftCount[b - 1] == 0 || n == 0)
          continue;
        double cost = leftArea[b - 1] * leftCount[b - 1] + acc.HalfArea * n;
        if (cost < bestCost)
        {
          bestCost = cost;
          bestSplit = b;
        }
      }

      double parentArea = Math.Max(bounds.HalfArea, 1e-300);
      double splitCost = TraversalCost + ItemCost * bestCost / parentArea;
      if (count <= MaxLeaf && (bestSplit < 0 || splitCost >= ItemCost * count))
        return self;

      if (bestSplit < 0)
        mid = (start + end) / 2;
      else
      {
        // Partition by bin index.
        int i = start, j = end - 1;
        while (i <= j)
        {
          int b = Math.Min(Bins - 1, (int)((centers[ids[i]][axis] - cmin) * scale));
          if (b < bestSplit)
            i++;
          else
          {
            (ids[i], ids[j]) = (ids[j], ids[i]);
            j--;
          }
        }
        mid = i;
        if (mid == start || mid == end)
          mid = (start + end) / 2;
      }
    }

    BuildNode(boxes, centers, ids, start, mid, nodes, level + 1, ref depth);
    int right = BuildNode(boxes, centers, ids, mid, end, nodes, level + 1, ref depth);
    BvhNode node = nodes[self];
    node.Index = right;
    node.Count = 0;
    node.Axis = axis;
    nodes[self] = node;
    return self;
  }

  static BvhNode Leaf(in Aabb b, int first, int count) => new()
  {
    MinX = b.Min.X, MinY = b.Min.Y, MinZ = b.Min.Z,
    MaxX = b.Max.X, MaxY = b.Max.Y, MaxZ = b.Max.Z,
    Index = first,
    Count = count,
  };
}
