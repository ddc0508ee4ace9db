using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Xunit;

namespace GrCis.Rendering.Tests.Meshes;

/// <summary>
/// <see cref="MeshCollapse"/>'s choice of wide nodes and leaf lanes (that every item is reached once inside every box
/// on its path is <see cref="MeshNodeTests"/>' collapse test).
/// </summary>
public class MeshCollapseTests
{
  [Fact]
  public void Eight_separate_clusters_are_one_wide_node_of_eight_leaf_lanes()
  {
    // Four tiny boxes at each corner of a cube: the SAH makes each corner a leaf (at most SmallLeaf items), and one
    // wide node holds all eight, as merging far corners into one leaf would cost far more.
    var boxes = new Aabb[32];
    for (int i = 0; i < boxes.Length; i++)
    {
      int corner = i / 4;
      var c = new Vector3d(corner & 1, (corner >> 1) & 1, corner >> 2) * 100.0 + new Vector3d(0.01 * (i % 4));
      boxes[i] = new Aabb(c, c + new Vector3d(0.1));
    }
    var ids = new int[boxes.Length];
    for (int i = 0; i < ids.Length; i++)
      ids[i] = i;
    Bvh tree = Bvh.Build(boxes, ids, BvhShape.Triangles);
    MeshNode[] nodes = MeshCollapse.Collapse(tree, BvhShape.Triangles, 0.0, out int stackSize);
    Assert.Single(nodes);
    Assert.Equal(MeshNode.Width + 1, stackSize);
    for (int lane = 0; lane < MeshNode.Width; lane++)
    {
      Assert.Equal(4, nodes[0].Count[lane]);
      Assert.Equal(4 * lane, nodes[0].Index[lane]);   // lanes in leaf order
    }
  }

  [Fact]
  public void A_split_pair_of_leaves_in_a_full_node_becomes_one_leaf_lane()
  {
    // Nine groups of four unit boxes: eight at the corners of a large cube, the ninth 0.6 beside the first. Each of
    // the pair's boxes has half area 3 of their union's 4.2: the SAH splits the pair (1 + 3·(3 + 3)/4.2 < 3·2 blocks),
    // but in a node with eight lanes for nine groups one leaf of two blocks (2·4.2) costs less than a wide node of its
    // own (4.2 + 3 + 3), or than merging far corners.
    var boxes = new Aabb[36];
    for (int i = 0; i < boxes.Length; i++)
    {
      int group = i / 4;
      Vector3d at = group < 8 ? new Vector3d(group & 1, (group >> 1) & 1, group >> 2) * 100.0 : new Vector3d(0.6, 0, 0);
      var c = at + new Vector3d(0.001 * (i % 4));
      boxes[i] = new Aabb(c, c + Vector3d.One);
    }
    var ids = new int[boxes.Length];
    for (int i = 0; i < ids.Length; i++)
      ids[i] = i;
    Bvh tree = Bvh.Build(boxes, ids, BvhShape.Triangles);
    int binaryLeaves = 0;
    foreach (BvhNode n in tree.Nodes)
      binaryLeaves += n.Count > 0 ? 1 : 0;
    Assert.Equal(9, binaryLeaves);
    MeshNode[] nodes = MeshCollapse.Collapse(tree, BvhShape.Triangles, 0.0, out _);
    Assert.Single(nodes);
    int items = 0, pairs = 0;
    for (int lane = 0; lane < MeshNode.Width; lane++)
    {
      Assert.True(nodes[0].Count[lane] is 4 or 8, $"lane {lane}: {nodes[0].Count[lane]} items");
      pairs += nodes[0].Count[lane] == 8 ? 1 : 0;
      items += nodes[0].Count[lane];
    }
    Assert.Equal(1, pairs);
    Assert.Equal(boxes.Length, items);
  }
}
