using Scene3D;
using System;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Xunit;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>
/// The block-aware SAH of <see cref="BvhShape.Triangles"/>: leaves and both sides of a split are costed in blocks of
/// <see cref="TriangleBlock.Width"/>, the unit the mesh stores and tests them in; the leaf limits hold; every triangle
/// is in one leaf and the mesh stores no more blocks than the SAH counted.
/// </summary>
public class BlockSahTests
{
  [Fact]
  public void The_triangle_shape_counts_in_the_mesh_s_blocks()
  {
    Assert.Equal(TriangleBlock.Width, BvhShape.Triangles.Block);
    Assert.Equal(1, BvhShape.SceneMembers.Block);
    Assert.Equal(16, BvhShape.SceneMembers.Bins);
    Assert.True(BvhShape.Triangles.Bins <= BvhBuilder.MaxBins);
    Assert.Equal(new[] { 0, 1, 1, 1, 1, 2, 2, 4, 5 }, Array.ConvertAll(new[] { 0, 1, 2, 3, 4, 5, 8, 16, 17 }, BvhShape.Triangles.Blocks));
  }

  [Fact]
  public void Five_overlapping_items_stay_one_leaf_of_two_blocks_where_per_item_costs_would_split_them()
  {
    // Unit boxes shifted by 0.25 along x (half area 5 together). The best plane leaves 2 | 3 items (half areas 3.5 and
    // 4): per item 1 + (2·3.5 + 3·4)/5 = 4.8 < 5, a split; in blocks 1 + (3.5 + 4)/5 = 2.5 > 2 blocks, a leaf.
    var boxes = new Aabb[5];
    var centers = new Vector3d[5];
    for (int i = 0; i < 5; i++)
    {
      boxes[i] = new Aabb(new Vector3d(0.25 * i, 0, 0), new Vector3d(0.25 * i + 1, 1, 1));
      centers[i] = boxes[i].Center;
    }
    Bvh perItem = Bvh.Build(boxes, centers, Identity(5), new BvhShape(4, 16, 1.0, Block: 1));
    Bvh perBlock = Bvh.Build(boxes, centers, Identity(5), new BvhShape(4, 16, 1.0, Block: 4));
    Assert.Equal(3, perItem.Nodes.Length);
    Assert.Single(perBlock.Nodes);
    Assert.Equal(5, perBlock.Nodes[0].Count);
  }

  [Theory]
  [InlineData(2_000)]
  [InlineData(60_000)]
  public void Triangle_leaves_respect_the_limits_and_hold_every_triangle_once(int triangles)
  {
    SceneBrep mesh = ProceduralMesh.TorusWithTriangles(triangles);
    var (boxes, centers) = TriangleBoxes(mesh);
    BvhShape shape = BvhShape.Triangles;
    Bvh tree = Bvh.Build(boxes, centers, Identity(boxes.Length), shape);
    var seen = new int[boxes.Length];
    int blocks = 0;
    Walk(0);
    Assert.All(seen, s => Assert.Equal(1, s));
    // The mesh lays each leaf lane out from a new block: the blocks its lanes count, never more than the SAH counted
    // (the collapse may make a subtree one leaf lane, whose items then share blocks).
    int laneBlocks = 0;
    foreach (MeshNode node in MeshCollapse.Collapse(tree, shape, 0.0, out _))
      for (int lane = 0; lane < MeshNode.Width; lane++)
        laneBlocks += shape.Blocks(node.Count[lane]);
    Assert.Equal(laneBlocks, new MeshBvh(mesh).BlockCount);
    Assert.InRange(laneBlocks, (mesh.Triangles + 3) / 4, blocks);

    int Walk(int node)
    {
      BvhNode n = tree.Nodes[node];
      if (n.Count > 0)
      {
        Assert.InRange(n.Count, 1, shape.LargeLeaf);
        for (int k = n.Index; k < n.Index + n.Count; k++)
          seen[tree.Items[k]]++;
        blocks += shape.Blocks(n.Count);
        return n.Count;
      }
      int count = Walk(node + 1) + Walk(n.Index);
      Assert.True(count > shape.SmallLeaf, $"node {node}: {count} items split, at most {shape.SmallLeaf} must stay a leaf");
      return count;
    }
  }

  static (Aabb[], Vector3d[]) TriangleBoxes(SceneBrep mesh)
  {
    var boxes = new Aabb[mesh.Triangles];
    var centers = new Vector3d[mesh.Triangles];
    for (int i = 0; i < boxes.Length; i++)
    {
      mesh.GetTriangleVertices(i, out Vector3 pa, out Vector3 pb, out Vector3 pc);
      Vector3d a = pa, b = pb, c = pc;
      boxes[i] = new Aabb(Vector3d.ComponentMin(a, Vector3d.ComponentMin(b, c)), Vector3d.ComponentMax(a, Vector3d.ComponentMax(b, c)));
      centers[i] = (a + b + c) / 3.0;
    }
    return (boxes, centers);
  }

  static int[] Identity(int n)
  {
    var ids = new int[n];
    for (int i = 0; i < n; i++)
      ids[i] = i;
    return ids;
  }
}
