using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>
/// The one bounding volume hierarchy, over scene members and over mesh triangles alike: built with
/// binned SAH on all three axes (<see cref="BvhBuilder"/>), stored as a flat node array (depth-first, left child adjacent, right
/// child at <see cref="BvhNode.Index"/>) so traversal is a loop over an index stack. What an item is
/// stays with the caller: leaves name item ids, in <see cref="Items"/>.
/// </summary>
internal sealed class Bvh
{
  public readonly BvhNode[] Nodes;

  /// <summary>Item ids in leaf order.</summary>
  public readonly int[] Items;

  /// <summary>Maximal depth (for sizing the traversal stack).</summary>
  public readonly int Depth;

  Bvh(BvhNode[] nodes, int[] items, int depth)
  {
    Nodes = nodes;
    Items = items;
    Depth = depth;
  }

  /// <summary>
  /// Builds over <paramref name="boxes"/>[ids[k]], split by <paramref name="centers"/>; <paramref name="ids"/>
  /// is reordered into leaf order and kept as <see cref="Items"/>. Traversals run on its <see cref="WideBvh"/>.
  /// <paramref name="threads"/> = 1 builds on the calling thread only; the tree is the same either way (<see cref="BvhBuilder"/>).
  /// </summary>
  public static Bvh Build(Aabb[] boxes, Vector3d[] centers, int[] ids, BvhShape shape, int threads = 0)
  {
    if (ids.Length == 0)
      return new Bvh([Leaf(new Aabb(Vector3d.Zero, Vector3d.Zero), 0, 0)], ids, 0);
    BvhNode[] nodes = BvhBuilder.Build(boxes, centers, ids, shape, threads, out int depth);
    return new Bvh(nodes, ids, depth);
  }

  /// <summary>Builds over boxes split by their centres.</summary>
  public static Bvh Build(Aabb[] boxes, int[] ids, BvhShape shape)
  {
    var centers = new Vector3d[boxes.Length];
    for (int i = 0; i < boxes.Length; i++)
      centers[i] = boxes[i].Center;
    return Build(boxes, centers, ids, shape);
  }

  /// <summary>
  /// The children a wide node over binary node <paramref name="binary"/> takes, in <paramref name="picks"/> (at most its
  /// length): the binary node's two children, then, while there is room, the inner one of largest surface area replaced
  /// by its two children, so the lanes stay in the binary tree's left-to-right order; a leaf (only the root can be one
  /// here) is its own single child. Returns how many. <see cref="WideBvh"/> picks by this rule; the mesh's eight-wide
  /// tree by least expected cost (<see cref="MeshCollapse"/>).
  /// </summary>
  public int WideChildren(int binary, System.Span<int> picks)
  {
    BvhNode[] b = Nodes;
    if (b[binary].Count > 0)
    {
      picks[0] = binary;
      return 1;
    }
    picks[0] = binary + 1;
    picks[1] = b[binary].Index;
    int count = 2;
    while (count < picks.Length)
    {
      int widest = -1;
      double area = -1.0;
      for (int k = 0; k < count; k++)
        if (b[picks[k]].Count == 0 && HalfArea(b[picks[k]]) > area)
        {
          area = HalfArea(b[picks[k]]);
          widest = k;
        }
      if (widest < 0)
        break;
      int inner = picks[widest];
      for (int k = count; k > widest + 1; k--)
        picks[k] = picks[k - 1];
      picks[widest] = inner + 1;
      picks[widest + 1] = b[inner].Index;
      count++;
    }
    return count;
  }

  static double HalfArea(in BvhNode n)
  {
    double x = n.MaxX - n.MinX, y = n.MaxY - n.MinY, z = n.MaxZ - n.MinZ;
    return x * y + y * z + z * x;
  }

  static BvhNode Leaf(in Aabb b, int first, int count) => new()
  {
    MinX = b.Min.X, MinY = b.Min.Y, MinZ = b.Min.Z,
    MaxX = b.Max.X, MaxY = b.Max.Y, MaxZ = b.Max.Z,
    Index = first,
    Count = count,
  };
}
