using Scene3D;
using System;
using System.Collections.Generic;
using System.IO;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Xunit;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>
/// <see cref="BvhBuilder"/>: the tree of the sequential builder it replaced (<see cref="ReferenceBvh"/>) to the last
/// bit, whatever the thread count; every item in exactly one leaf; every box around its children.
/// </summary>
public class BvhBuilderTests
{
  public static TheoryData<string> Inputs() => new()
  {
    "vase", "torus-20k", "cube", "random-members", "same-centres", "flat", "signed-zeros", "one", "two",
  };

  [Theory]
  [MemberData(nameof(Inputs))]
  public void Build_gives_the_sequential_builders_tree_to_the_bit(string name)
  {
    var (boxes, centers, shape) = Input(name);
    int[] expectedIds = Identity(boxes.Length), ids = Identity(boxes.Length);
    var (expected, expectedDepth) = ReferenceBvh.Build(boxes, centers, expectedIds, shape);
    foreach (int threads in new[] { 1, 2, 0 })
    {
      ids = Identity(boxes.Length);
      Bvh tree = Bvh.Build(boxes, centers, ids, shape, threads);
      Assert.Equal(expectedIds, tree.Items);
      Assert.Equal(expectedDepth, tree.Depth);
      Assert.Equal(expected.Length, tree.Nodes.Length);
      for (int i = 0; i < expected.Length; i++)
        AssertSame(expected[i], tree.Nodes[i], $"{name}, {threads} threads, node {i}");
    }
  }

  [Theory]
  [MemberData(nameof(Inputs))]
  public void Every_item_is_in_one_leaf_and_every_box_holds_its_children(string name)
  {
    var (boxes, centers, shape) = Input(name);
    Bvh tree = Bvh.Build(boxes, centers, Identity(boxes.Length), shape);
    var seen = new int[boxes.Length];
    int depth = Walk(tree, boxes, 0, 1, seen);
    Assert.All(seen, s => Assert.Equal(1, s));
    Assert.Equal(tree.Depth, depth);
    // Leaf ranges tile Items, so every node is reachable from the root.
    Assert.Equal(tree.Nodes.Length, CountReachable(tree, 0));
  }

  [Fact]
  public void Large_mesh_builds_the_same_tree_on_one_thread_and_on_two()
  {
    // Large enough that subtrees are forked (BvhBuilder.ParallelItems).
    var (boxes, centers, shape) = Triangles(ProceduralMesh.TorusWithTriangles(60_000));
    Assert.True(boxes.Length >= 4 * BvhBuilder.ParallelItems);
    Bvh one = Bvh.Build(boxes, centers, Identity(boxes.Length), shape, threads: 1);
    for (int round = 0; round < 3; round++)
    {
      Bvh two = Bvh.Build(boxes, centers, Identity(boxes.Length), shape, threads: 2);
      Assert.Equal(one.Items, two.Items);
      Assert.Equal(one.Depth, two.Depth);
      Assert.Equal(one.Nodes.Length, two.Nodes.Length);
      for (int i = 0; i < one.Nodes.Length; i++)
        AssertSame(one.Nodes[i], two.Nodes[i], $"round {round}, node {i}");
    }
  }

  static int Walk(Bvh tree, Aabb[] boxes, int node, int level, int[] seen)
  {
    BvhNode n = tree.Nodes[node];
    Assert.True(n.MinX <= n.MaxX && n.MinY <= n.MaxY && n.MinZ <= n.MaxZ, $"node {node} is empty");
    if (n.Count > 0)
    {
      for (int k = n.Index; k < n.Index + n.Count; k++)
      {
        int id = tree.Items[k];
        seen[id]++;
        Aabb b = boxes[id];
        Assert.True(Contains(n, b.Min.X, b.Min.Y, b.Min.Z, b.Max.X, b.Max.Y, b.Max.Z), $"leaf {node} does not hold item {id}");
      }
      return level;
    }
    foreach (int child in new[] { node + 1, n.Index })
    {
      BvhNode c = tree.Nodes[child];
      Assert.True(child > node, $"node {node}: child {child} is not after it");
      Assert.True(Contains(n, c.MinX, c.MinY, c.MinZ, c.MaxX, c.MaxY, c.MaxZ), $"node {node} does not hold child {child}");
    }
    return Math.Max(Walk(tree, boxes, node + 1, level + 1, seen), Walk(tree, boxes, n.Index, level + 1, seen));
  }

  static int CountReachable(Bvh tree, int node) =>
    tree.Nodes[node].Count > 0 ? 1 : 1 + CountReachable(tree, node + 1) + CountReachable(tree, tree.Nodes[node].Index);

  static bool Contains(in BvhNode n, double x0, double y0, double z0, double x1, double y1, double z1) =>
    n.MinX <= x0 && n.MinY <= y0 && n.MinZ <= z0 && x1 <= n.MaxX && y1 <= n.MaxY && z1 <= n.MaxZ;

  static void AssertSame(in BvhNode want, in BvhNode have, string where)
  {
    double[] w = { want.MinX, want.MinY, want.MinZ, want.MaxX, want.MaxY, want.MaxZ };
    double[] h = { have.MinX, have.MinY, have.MinZ, have.MaxX, have.MaxY, have.MaxZ };
    for (int i = 0; i < 6; i++)
      Assert.True(BitConverter.DoubleToInt64Bits(w[i]) == BitConverter.DoubleToInt64Bits(h[i]), $"{where}: box coordinate {i} {w[i]:R} vs {h[i]:R}");
    Assert.True(want.Index == have.Index && want.Count == have.Count && want.Axis == have.Axis,
      $"{where}: ({want.Index}, {want.Count}, {want.Axis}) vs ({have.Index}, {have.Count}, {have.Axis})");
  }

  static int[] Identity(int n)
  {
    var ids = new int[n];
    for (int i = 0; i < n; i++)
      ids[i] = i;
    return ids;
  }

  static (Aabb[] Boxes, Vector3d[] Centers, BvhShape Shape) Input(string name)
  {
    var rnd = new Random(17);
    switch (name)
    {
      case "vase":
        var vase = new SceneBrep();
        new WavefrontObj().ReadBrep(new StringReader(File.ReadAllText(Path.Combine(RepositoryRoot(), "scripts", "data", "vase.obj"))), vase);
        return Triangles(vase);
      case "torus-20k":
        return Triangles(ProceduralMesh.TorusWithTriangles(20_000));
      case "cube":
        return Triangles(Meshes.MeshTestSupport.Read(Meshes.MeshTestSupport.CubeObj));
      case "random-members":
        return Members(3_000, i => new Vector3d(rnd.NextDouble(), rnd.NextDouble(), rnd.NextDouble()) * 10.0, rnd);
      case "same-centres":   // inseparable: halves in the current order
        return Members(300, i => new Vector3d(1, 2, 3), rnd);
      case "flat":           // all centres on a plane, boxes without depth: zero areas
        return Members(500, i => new Vector3d(rnd.Next(20), rnd.Next(20), 0), rnd, flat: true);
      case "signed-zeros":   // ties of −0 and +0 in every union: the sign must come out as Math.Min's
        return SignedZeros(rnd);
      case "one":
        return Members(1, i => Vector3d.One, rnd);
      default:
        return Members(2, i => new Vector3d(i, -i, 0.5 * i), rnd);
    }
  }

  static (Aabb[], Vector3d[], BvhShape) Members(int n, Func<int, Vector3d> center, Random rnd, bool flat = false)
  {
    var boxes = new Aabb[n];
    for (int i = 0; i < n; i++)
    {
      Vector3d c = center(i);
      var half = new Vector3d(rnd.NextDouble(), rnd.NextDouble(), flat ? 0.0 : rnd.NextDouble()) * 0.5;
      boxes[i] = new Aabb(c - half, c + half);
    }
    var centers = new Vector3d[n];
    for (int i = 0; i < n; i++)
      centers[i] = boxes[i].Center;
    return (boxes, centers, BvhShape.SceneMembers);
  }

  static (Aabb[], Vector3d[], BvhShape) SignedZeros(Random rnd)
  {
    double Pick() => rnd.Next(4) switch { 0 => -0.0, 1 => 0.0, 2 => -1.0, _ => 1.0 };
    var boxes = new Aabb[600];
    var centers = new Vector3d[boxes.Length];
    for (int i = 0; i < boxes.Length; i++)
    {
      Vector3d a = new(Pick(), Pick(), Pick()), b = new(Pick(), Pick(), Pick());
      boxes[i] = new Aabb(Vector3d.ComponentMin(a, b), Vector3d.ComponentMax(a, b));
      centers[i] = new Vector3d(Pick(), Pick(), Pick());
    }
    return (boxes, centers, BvhShape.SceneMembers);
  }

  /// <summary>Triangle boxes and centroids as <see cref="MeshBvh"/> makes them.</summary>
  static (Aabb[], Vector3d[], BvhShape) Triangles(SceneBrep mesh)
  {
    int n = mesh.Triangles;
    var boxes = new Aabb[n];
    var centers = new Vector3d[n];
    for (int i = 0; i < n; i++)
    {
      mesh.GetTriangleVertices(i, out Vector3 pa, out Vector3 pb, out Vector3 pc);
      Vector3d a = pa, b = pb, c = pc;
      boxes[i] = new Aabb(Vector3d.ComponentMin(a, Vector3d.ComponentMin(b, c)), Vector3d.ComponentMax(a, Vector3d.ComponentMax(b, c)));
      centers[i] = (a + b + c) / 3.0;
    }
    return (boxes, centers, BvhShape.Triangles);
  }

  static string RepositoryRoot()
  {
    for (DirectoryInfo? d = new(AppContext.BaseDirectory); d != null; d = d.Parent)
      if (File.Exists(Path.Combine(d.FullName, "GrCis.sln")))
        return d.FullName;
    throw new InvalidOperationException("GrCis.sln not found above " + AppContext.BaseDirectory);
  }
}
