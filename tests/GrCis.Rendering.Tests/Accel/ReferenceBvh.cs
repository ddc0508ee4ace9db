using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>
/// The sequential builder <see cref="Bvh"/> used before <see cref="BvhBuilder"/> (the same rule, node by node, with a
/// rescan of every node's items): the new builder must give its tree to the last bit, so images stay byte-identical.
/// </summary>
internal static class ReferenceBvh
{
  const double TraversalCost = 1.0;

  public static (BvhNode[] Nodes, int Depth) Build(Aabb[] boxes, Vector3d[] centers, int[] ids, BvhShape shape)
  {
    var nodes = new List<BvhNode>(Math.Max(1, 2 * ids.Length));
    int depth = 0;
    new Builder(boxes, centers, ids, shape, nodes).Node(0, ids.Length, 1, ref depth);
    return (nodes.ToArray(), depth);
  }

  static BvhNode Leaf(in Aabb b, int first, int count) => new()
  {
    MinX = b.Min.X, MinY = b.Min.Y, MinZ = b.Min.Z,
    MaxX = b.Max.X, MaxY = b.Max.Y, MaxZ = b.Max.Z,
    Index = first,
    Count = count,
  };

  readonly struct Builder(Aabb[] boxes, Vector3d[] centers, int[] ids, BvhShape shape, List<BvhNode> nodes)
  {
    public int Node(int start, int end, int level, ref int depth)
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
      if (count <= shape.SmallLeaf)
        return self;

      Split split = BestSplit(start, end, cbounds);
      double leafCost = shape.BlockCost * shape.Blocks(count);
      double parentArea = bounds.HalfArea;
      double splitCost = split.Axis >= 0 && parentArea > 0.0
        ? TraversalCost + shape.BlockCost * split.Cost / parentArea
        : double.PositiveInfinity;
      int mid;
      if (splitCost < leafCost || (count > shape.LargeLeaf && split.Axis >= 0))
        mid = Partition(start, end, cbounds, split);
      else if (count > shape.LargeLeaf)
        mid = (start + end) / 2;   // inseparable centres: halves in the current order
      else
        return self;
      if (mid == start || mid == end)
        mid = (start + end) / 2;

      Node(start, mid, level + 1, ref depth);
      int right = Node(mid, end, level + 1, ref depth);
      BvhNode node = nodes[self];
      node.Index = right;
      node.Count = 0;
      node.Axis = split.Axis >= 0 ? split.Axis : 0;
      nodes[self] = node;
      return self;
    }

    /// <summary>The cheapest of the bin planes on the three axes (SAH, unnormalised); Axis −1 when none separates.</summary>
    Split BestSplit(int start, int end, in Aabb cbounds)
    {
      int bins = shape.Bins;
      Span<int> binCount = stackalloc int[bins];
      Span<Aabb> binBox = stackalloc Aabb[bins];
      Span<double> rightArea = stackalloc double[bins];
      Span<int> rightCount = stackalloc int[bins];
      var best = new Split(-1, 0, double.PositiveInfinity);
      for (int axis = 0; axis < 3; axis++)
      {
        double cmin = cbounds.Min[axis], extent = cbounds.Max[axis] - cmin;
        if (!(extent > 0.0))
          continue;
        double scale = bins / extent;
        binCount.Clear();
        binBox.Fill(Aabb.Empty);
        for (int k = start; k < end; k++)
        {
          int b = Bin(centers[ids[k]][axis], cmin, scale, bins);
          binCount[b]++;
          binBox[b].Add(boxes[ids[k]]);
        }
        Aabb acc = Aabb.Empty;
        int n = 0;
        for (int b = bins - 1; b > 0; b--)
        {
          acc.Add(binBox[b]);
          n += binCount[b];
          rightCount[b] = n;
          rightArea[b] = acc.HalfArea;
        }
        acc = Aabb.Empty;
        n = 0;
        for (int b = 1; b < bins; b++)
        {
          acc.Add(binBox[b - 1]);
          n += binCount[b - 1];
          if (n == 0 || rightCount[b] == 0)
            continue;
          double cost = shape.Blocks(n) * acc.HalfArea + shape.Blocks(rightCount[b]) * rightArea[b];
          if (cost < best.Cost)
            best = new Split(axis, b, cost);
        }
      }
      return best;
    }

    /// <summary>Items whose centre falls in a bin below the split plane first; returns the first of the rest.</summary>
    int Partition(int start, int end, in Aabb cbounds, Split split)
    {
      int bins = shape.Bins;
      double cmin = cbounds.Min[split.Axis], scale = bins / (cbounds.Max[split.Axis] - cmin);
      int i = start, j = end - 1;
      while (i <= j)
      {
        if (Bin(centers[ids[i]][split.Axis], cmin, scale, bins) < split.Bin)
          i++;
        else
        {
          (ids[i], ids[j]) = (ids[j], ids[i]);
          j--;
        }
      }
      return i;
    }

    static int Bin(double c, double cmin, double scale, int bins) => Math.Min(bins - 1, (int)((c - cmin) * scale));
  }

  readonly record struct Split(int Axis, int Bin, double Cost);
}
