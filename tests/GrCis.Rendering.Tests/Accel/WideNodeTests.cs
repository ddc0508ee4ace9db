using System;
using System.Runtime.Intrinsics;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace GrCis.Rendering.Tests.Accel;

public class WideNodeTests
{
  static readonly double[] Specials =
  {
    0.0, -0.0, 1.0, -1.0, 1e-300, -1e-300, 1e300, double.PositiveInfinity, double.NegativeInfinity, double.NaN, 2.5, -3.25,
  };

  static BvhNode Box(Random r, bool special)
  {
    double Coord() => special && r.Next(4) == 0 ? Specials[r.Next(Specials.Length)] : r.NextDouble() * 8.0 - 4.0;
    double x0 = Coord(), x1 = Coord(), y0 = Coord(), y1 = Coord(), z0 = Coord(), z1 = Coord();
    // Mostly proper boxes, sometimes inverted (empty) or degenerate (flat) ones.
    if (r.Next(5) != 0)
    {
      (x0, x1) = (Math.Min(x0, x1), Math.Max(x0, x1));
      (y0, y1) = (Math.Min(y0, y1), Math.Max(y0, y1));
      (z0, z1) = (Math.Min(z0, z1), Math.Max(z0, z1));
    }
    if (r.Next(10) == 0)
      x1 = x0;
    return new BvhNode { MinX = x0, MaxX = x1, MinY = y0, MaxY = y1, MinZ = z0, MaxZ = z1 };
  }

  static WideNode Node(BvhNode[] boxes, int lanes)
  {
    var node = new WideNode();
    for (int l = 0; l < lanes; l++)
      node.SetBox(l, boxes[l], 0.0);
    return node;
  }

  [Fact]
  public void Four_box_simd_test_answers_as_the_scalar_slab_test_for_each_box()
  {
    var r = new Random(1234);
    int hits = 0, misses = 0;
    var boxes = new BvhNode[WideNode.Width];
    for (int n = 0; n < 200_000; n++)
    {
      bool special = n % 3 == 0;
      for (int l = 0; l < boxes.Length; l++)
        boxes[l] = Box(r, special);
      int lanes = 1 + n % WideNode.Width;
      BvhNode a = boxes[0];
      double Origin() => special && r.Next(6) == 0 ? Specials[r.Next(Specials.Length)] : r.NextDouble() * 12.0 - 6.0;
      double Dir() => special && r.Next(3) == 0 ? Specials[r.Next(Specials.Length)] : r.NextDouble() * 2.0 - 1.0;
      double ox = Origin(), oy = Origin(), oz = Origin();
      // Inverse directions as the traversal makes them (zero → 1e-300), plus raw ±∞ and NaN.
      double ix = 1.0 / Dir(), iy = 1.0 / Dir(), iz = 1.0 / Dir();
      if (n % 2 == 1)
      {
        // Aimed at the first box's centre: plenty of hits.
        ix = 1.0 / (0.5 * (a.MinX + a.MaxX) - ox);
        iy = 1.0 / (0.5 * (a.MinY + a.MaxY) - oy);
        iz = 1.0 / (0.5 * (a.MinZ + a.MaxZ) - oz);
      }
      if (n % 7 == 0)
        ox = a.MinX; // origin on a slab plane: 0 · ∞ when the direction is parallel
      double best = n % 5 switch
      {
        0 => double.PositiveInfinity,
        1 => r.NextDouble() * 3.0,
        2 => 0.0,
        3 => double.NaN,
        _ => 1.0 + 1e-12,
      };

      WideNode node = Node(boxes, lanes);
      int bits = node.Hit(Vector256.Create(ox), Vector256.Create(oy), Vector256.Create(oz),
                          Vector256.Create(ix), Vector256.Create(iy), Vector256.Create(iz), best, out Vector256<double> entry);
      Assert.Equal(0, bits >> lanes);   // unused lanes never answer
      for (int l = 0; l < lanes; l++)
      {
        bool h = WideNode.Slab(boxes[l], ox, oy, oz, ix, iy, iz, best, out double e);
        Assert.Equal(h, (bits & (1 << l)) != 0);
        // The entry t is re-checked against a smaller best after a push: it must compare the same way.
        if (h)
          Assert.True(entry.GetElement(l) == e, $"lane {l} entry {entry.GetElement(l)} vs {e}");
        if (h) hits++; else misses++;
      }
    }
    // Both outcomes occur often enough for the comparison to mean something.
    Assert.True(hits > 50_000 && misses > 50_000, $"{hits} hits, {misses} misses");
  }

  /// <summary>The whole line against one box, slab by slab; a NaN slab (d = 0, origin on its plane) does not restrict it.</summary>
  static bool LineCrosses(in BvhNode b, double ox, double oy, double oz, double ix, double iy, double iz, out double near, out double far)
  {
    near = double.NegativeInfinity;
    far = double.PositiveInfinity;
    foreach ((double min, double max, double o, double inv) in new[] { (b.MinX, b.MaxX, ox, ix), (b.MinY, b.MaxY, oy, iy), (b.MinZ, b.MaxZ, oz, iz) })
    {
      double t0 = (min - o) * inv, t1 = (max - o) * inv;
      if (double.IsNaN(t0) || double.IsNaN(t1))
        continue;
      near = Math.Max(near, Math.Min(t0, t1));
      far = Math.Min(far, Math.Max(t0, t1));
    }
    return near <= far;
  }

  [Fact]
  public void Four_box_line_test_answers_as_a_scalar_line_test_for_each_box()
  {
    var r = new Random(77);
    int crossed = 0, missed = 0;
    var boxes = new BvhNode[WideNode.Width];
    for (int n = 0; n < 100_000; n++)
    {
      bool special = n % 3 == 0;
      for (int l = 0; l < boxes.Length; l++)
        boxes[l] = Box(r, special);
      int lanes = 1 + n % WideNode.Width;
      double Origin() => special && r.Next(6) == 0 ? Specials[r.Next(Specials.Length)] : r.NextDouble() * 12.0 - 6.0;
      double Dir() => special && r.Next(3) == 0 ? (r.Next(2) == 0 ? 0.0 : -0.0) : r.NextDouble() * 2.0 - 1.0;
      double ox = Origin(), oy = Origin(), oz = Origin();
      if (n % 7 == 0)
        oy = boxes[0].MaxY; // on a slab plane
      double ix = 1.0 / Dir(), iy = 1.0 / Dir(), iz = 1.0 / Dir();

      WideNode node = Node(boxes, lanes);
      int bits = node.Valid & WideNode.Cross(node.MinX, node.MaxX, node.MinY, node.MaxY, node.MinZ, node.MaxZ,
                                             Vector256.Create(ox), Vector256.Create(oy), Vector256.Create(oz),
                                             Vector256.Create(ix), Vector256.Create(iy), Vector256.Create(iz), out Vector256<double> near, out Vector256<double> far);
      Assert.Equal(0, bits >> lanes);
      for (int l = 0; l < lanes; l++)
      {
        bool c = LineCrosses(boxes[l], ox, oy, oz, ix, iy, iz, out double tn, out double tf);
        Assert.Equal(c, (bits & (1 << l)) != 0);
        if (c)
        {
          Assert.True(near.GetElement(l) == tn && far.GetElement(l) == tf, $"lane {l}: [{near.GetElement(l)}, {far.GetElement(l)}] vs [{tn}, {tf}]");
          crossed++;
        }
        else
          missed++;
      }
    }
    Assert.True(crossed > 20_000 && missed > 20_000, $"{crossed} crossed, {missed} missed");
  }

  [Theory]
  [InlineData(1)]
  [InlineData(2)]
  [InlineData(5)]
  [InlineData(37)]
  [InlineData(2000)]
  public void Collapsed_tree_keeps_every_leaf_once_inside_its_ancestors_boxes(int count)
  {
    var r = new Random(count);
    var boxes = new Aabb[count];
    var ids = new int[count];
    for (int i = 0; i < count; i++)
    {
      var c = new OpenTK.Mathematics.Vector3d(r.NextDouble() * 20, r.NextDouble() * 20, r.NextDouble() * 20);
      var h = new OpenTK.Mathematics.Vector3d(r.NextDouble(), r.NextDouble(), r.NextDouble());
      boxes[i] = new Aabb(c - h, c + h);
      ids[i] = i;
    }
    foreach (BvhShape shape in new[] { BvhShape.SceneMembers, BvhShape.Triangles })
    {
      Bvh tree = Bvh.Build(boxes, (int[])ids.Clone(), shape);
      WideBvh wide = WideBvh.Collapse(tree);
      var seen = new int[count];
      int maxLive = Walk(wide, 0, boxes, seen, null);
      Assert.All(seen, s => Assert.Equal(1, s));
      // Inner nodes other than the root's only child chain are full: the collapse pulls grandchildren up.
      if (count > 16)
        Assert.True(wide.Nodes.Length * 2 < tree.Nodes.Length, $"{wide.Nodes.Length} wide vs {tree.Nodes.Length} binary nodes");
      Assert.True(maxLive <= wide.StackSize);
    }
  }

  /// <summary>Checks lane boxes contain what lies below; counts items; returns the deepest stack a traversal could need.</summary>
  static int Walk(WideBvh wide, int node, Aabb[] boxes, int[] seen, Aabb? parent)
  {
    ref WideNode n = ref wide.Nodes[node];
    int lanes = System.Numerics.BitOperations.PopCount((uint)n.Valid);
    Assert.True(lanes >= 1);
    int deepest = 0;
    for (int l = 0; l < lanes; l++)
    {
      var box = new Aabb(new OpenTK.Mathematics.Vector3d(n.MinX.GetElement(l), n.MinY.GetElement(l), n.MinZ.GetElement(l)),
                         new OpenTK.Mathematics.Vector3d(n.MaxX.GetElement(l), n.MaxY.GetElement(l), n.MaxZ.GetElement(l)));
      if (parent is Aabb p)
        Assert.True(Inside(box, p));
      if (n.Count[l] > 0)
        for (int k = n.Index[l]; k < n.Index[l] + n.Count[l]; k++)
        {
          seen[wide.Items[k]]++;
          Assert.True(Inside(boxes[wide.Items[k]], box));
        }
      else
        deepest = Math.Max(deepest, Walk(wide, n.Index[l], boxes, seen, box));
    }
    // This node's pop leaves its lanes on the stack, one of which is popped next.
    return lanes - 1 + Math.Max(1, deepest);
  }

  static bool Inside(in Aabb a, in Aabb b) =>
    a.Min.X >= b.Min.X && a.Min.Y >= b.Min.Y && a.Min.Z >= b.Min.Z && a.Max.X <= b.Max.X && a.Max.Y <= b.Max.Y && a.Max.Z <= b.Max.Z;
}
