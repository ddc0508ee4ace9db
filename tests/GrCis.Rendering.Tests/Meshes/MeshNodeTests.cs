using System;
using System.Collections.Generic;
using System.Runtime.Intrinsics;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;

namespace GrCis.Rendering.Tests.Meshes;

/// <summary>
/// The mesh tree's eight-wide float nodes: the float box step (and its double fallback) never drops a box the exact
/// double slab test keeps, and its intervals contain the double ones; the collapse reaches every item exactly once.
/// </summary>
public class MeshNodeTests
{
  static readonly double[] Scales = { 1e-30, 1e-6, 1.0, 1e6, 1e30, 1e37 };

  // A box around c of size up to s (sometimes flat, sometimes tiny within a huge scene).
  static BvhNode Box(Random r, Vector3d c, double s)
  {
    double Coord(double center) => center + (r.NextDouble() * 2.0 - 1.0) * s;
    double x0 = Coord(c.X), x1 = Coord(c.X), y0 = Coord(c.Y), y1 = Coord(c.Y), z0 = Coord(c.Z), z1 = Coord(c.Z);
    if (r.Next(8) == 0)
      x1 = x0;
    if (r.Next(8) == 0)
      (y1, z1) = (y0 + s * 1e-9, z0 + s * 1e-12);
    return new BvhNode
    {
      MinX = Math.Min(x0, x1), MaxX = Math.Max(x0, x1), MinY = Math.Min(y0, y1), MaxY = Math.Max(y0, y1),
      MinZ = Math.Min(z0, z1), MaxZ = Math.Max(z0, z1),
    };
  }

  [Fact]
  public void Float_step_keeps_every_box_the_double_test_keeps_with_a_containing_interval()
  {
    var r = new Random(4711);
    var boxes = new BvhNode[MeshNode.Width];
    int kept = 0, fast = 0, slow = 0;
    for (int n = 0; n < 100_000; n++)
    {
      double s = Scales[r.Next(Scales.Length)];
      // Mostly around the origin, sometimes far from it (a mesh 10^6 of its sizes away).
      Vector3d c = r.Next(3) == 0 ? new Vector3d(1e6 * s, -3e5 * s, 2e6 * s) : Vector3d.Zero;
      int lanes = 1 + r.Next(MeshNode.Width);
      var node = new MeshNode();
      node.Clear();
      for (int l = 0; l < lanes; l++)
      {
        boxes[l] = Box(r, c, s);
        node.SetBox(l, boxes[l], 0.0);
      }
      BvhNode a = boxes[r.Next(lanes)];
      Vector3d o = (r.Next(4)) switch
      {
        0 => c + 1e8 * s * new Vector3d(r.NextDouble() - 0.5, r.NextDouble() - 0.5, r.NextDouble() - 0.5),   // far away
        1 => new Vector3d(a.MinX, r.Next(2) == 0 ? a.MaxY : a.MinY, a.MaxZ),                               // on box planes
        _ => c + 3.0 * s * new Vector3d(r.NextDouble() - 0.5, r.NextDouble() - 0.5, r.NextDouble() - 0.5),
      };
      Vector3d target = new Vector3d(a.MinX + r.NextDouble() * (a.MaxX - a.MinX), a.MinY + r.NextDouble() * (a.MaxY - a.MinY),
                                     a.MinZ + r.NextDouble() * (a.MaxZ - a.MinZ));
      Vector3d d = r.Next(2) == 0 ? target - o : new Vector3d(r.NextDouble() - 0.5, r.NextDouble() - 0.5, r.NextDouble() - 0.5);
      // Axis-parallel (±0 components), nearly so, and scaled directions.
      if (r.Next(4) == 0)
        d.X = r.Next(2) == 0 ? 0.0 : -0.0;
      if (r.Next(8) == 0)
        d.Y = d.Y * 1e-25;
      if (r.Next(8) == 0)
        d *= r.Next(2) == 0 ? 1e-20 : 1e20;
      var line = new MeshLine(o.X, o.Y, o.Z, d.X, d.Y, d.Z);

      // The reference: the exact double slab test of the double boxes (NaN slabs do not restrict the line).
      var lo = new WideNode();
      var hi = new WideNode();
      for (int l = 0; l < lanes; l++)
        (l < WideNode.Width ? ref lo : ref hi).SetBox(l % WideNode.Width, boxes[l], 0.0);
      Vector256<double> ox = Vector256.Create(o.X), oy = Vector256.Create(o.Y), oz = Vector256.Create(o.Z);
      Vector256<double> ix = Vector256.Create(line.Ix), iy = Vector256.Create(line.Iy), iz = Vector256.Create(line.Iz);
      int want = lo.Valid & WideNode.Cross(lo.MinX, lo.MaxX, lo.MinY, lo.MaxY, lo.MinZ, lo.MaxZ, ox, oy, oz, ix, iy, iz, out Vector256<double> nearLo, out Vector256<double> farLo) |
                 (hi.Valid & WideNode.Cross(hi.MinX, hi.MaxX, hi.MinY, hi.MaxY, hi.MinZ, hi.MaxZ, ox, oy, oz, ix, iy, iz, out Vector256<double> nearHi, out Vector256<double> farHi)) << 4;

      double mx = 0, my = 0, mz = 0;
      for (int l = 0; l < lanes; l++)
      {
        mx = Math.Max(mx, Math.Max(Math.Abs((double)node.MinX[l]), Math.Abs((double)node.MaxX[l])));
        my = Math.Max(my, Math.Max(Math.Abs((double)node.MinY[l]), Math.Abs((double)node.MaxY[l])));
        mz = Math.Max(mz, Math.Max(Math.Abs((double)node.MinZ[l]), Math.Abs((double)node.MaxZ[l])));
      }
      if (FloatStep.Bounded(line, mx, my, mz))
      {
        var step = new FloatStep(line, mx, my, mz);
        Check(step.Cross(in node, out Vector256<float> near, out Vector256<float> far), near, far);
        fast++;
      }
      else
        slow++;
      // The fallback must hold for every ray, bounded or not.
      Check(new DoubleStep(line).Cross(in node, out Vector256<float> dn, out Vector256<float> df), dn, df);
      kept += System.Numerics.BitOperations.PopCount((uint)want);

      void Check(int got, Vector256<float> near, Vector256<float> far)
      {
        for (int l = 0; l < lanes; l++)
        {
          if ((want >> l & 1) == 0)
            continue;
          double wn = l < 4 ? nearLo[l] : nearHi[l - 4], wf = l < 4 ? farLo[l] : farHi[l - 4];
          Assert.True((got >> l & 1) != 0, $"n={n}: lane {l} dropped, double [{wn}, {wf}], float [{near[l]}, {far[l]}], o {o}, d {d}");
          Assert.True(near[l] <= wn && far[l] >= wf, $"n={n}: lane {l} float [{near[l]}, {far[l]}] does not contain double [{wn}, {wf}], o {o}, d {d}");
        }
        Assert.Equal(0, got & ~((1 << lanes) - 1) & (int)Vector256.LessThanOrEqual(node.MinX, node.MaxX).ExtractMostSignificantBits());
        Assert.Equal(0, got >> lanes);   // unused lanes are never crossed
      }
    }
    Assert.True(kept > 80_000 && fast > 40_000 && slow > 5_000, $"kept {kept}, float {fast}, fallback {slow}: cases not exercised");
  }

  [Fact]
  public void Collapse_reaches_every_item_exactly_once_inside_every_box_on_its_path()
  {
    var r = new Random(99);
    foreach (int n in new[] { 1, 2, 7, 9, 100, 5000 })
    {
      var boxes = new Aabb[n];
      for (int i = 0; i < n; i++)
      {
        BvhNode b = Box(r, new Vector3d(r.NextDouble() * 100, r.NextDouble() * 100, r.NextDouble()), 1.0 + i % 3);
        boxes[i] = new Aabb(new Vector3d(b.MinX, b.MinY, b.MinZ), new Vector3d(b.MaxX, b.MaxY, b.MaxZ));
      }
      var ids = new int[n];
      for (int i = 0; i < n; i++)
        ids[i] = i;
      Bvh tree = Bvh.Build(boxes, ids, BvhShape.Triangles);
      MeshNode[] nodes = MeshCollapse.Collapse(tree, BvhShape.Triangles, 0.0, out int stackSize);
      var seen = new int[n];
      var visited = new bool[nodes.Length];
      int maxDepth = 0;
      Walk(0, Aabb.Empty, 0);
      Assert.All(seen, c => Assert.Equal(1, c));
      Assert.All(visited, v => Assert.True(v));
      Assert.True(stackSize >= (MeshNode.Width - 1) * maxDepth + 1, $"stack {stackSize} for depth {maxDepth}");

      void Walk(int node, Aabb parent, int depth)
      {
        Assert.False(visited[node], $"node {node} reached twice");
        visited[node] = true;
        maxDepth = Math.Max(maxDepth, depth);
        ref MeshNode m = ref nodes[node];
        for (int l = 0; l < MeshNode.Width; l++)
        {
          if (!(m.MinX[l] <= m.MaxX[l]))
          {
            Assert.True(m.MinX[l] == float.PositiveInfinity && m.MaxZ[l] == float.NegativeInfinity && m.Count[l] == 0);
            continue;
          }
          var box = new Aabb(new Vector3d(m.MinX[l], m.MinY[l], m.MinZ[l]), new Vector3d(m.MaxX[l], m.MaxY[l], m.MaxZ[l]));
          if (node != 0)
            Assert.True(Inside(box, parent), $"node {node} lane {l}: child box outside its parent's");
          if (m.Count[l] == 0)
          {
            Walk(m.Index[l], box, depth + 1);
            continue;
          }
          Assert.InRange(m.Count[l], 1, BvhShape.Triangles.LargeLeaf);   // a merged subtree is a leaf only within the limit
          for (int k = m.Index[l]; k < m.Index[l] + m.Count[l]; k++)
          {
            int item = tree.Items[k];
            seen[item]++;
            Assert.True(Inside(boxes[item], box), $"item {item} outside its leaf's float box");
          }
        }
      }
    }
  }

  static bool Inside(in Aabb a, in Aabb b) =>
    a.Min.X >= b.Min.X && a.Min.Y >= b.Min.Y && a.Min.Z >= b.Min.Z && a.Max.X <= b.Max.X && a.Max.Y <= b.Max.Y && a.Max.Z <= b.Max.Z;

  [Fact]
  public void Children_gives_each_lane_s_child_code()
  {
    var r = new Random(5);
    var node = new MeshNode();
    for (int n = 0; n < 10_000; n++)
    {
      for (int lane = 0; lane < MeshNode.Width; lane++)
      {
        node.Index[lane] = r.Next(int.MaxValue);
        node.Count[lane] = r.Next(3) == 0 ? 0 : r.Next(1, 100);
      }
      int self = r.Next(n % 2 == 0 ? 1000 : int.MaxValue / MeshNode.Width);
      Vector256<int> codes = node.Children(self);
      for (int lane = 0; lane < MeshNode.Width; lane++)
      {
        Assert.Equal(node.Child(self, lane), codes.GetElement(lane));
        Assert.Equal(node.Count[lane] == 0, codes.GetElement(lane) >= 0);
      }
    }
  }

  [Fact]
  public void Outward_rounding_brackets_the_double()
  {
    var r = new Random(5);
    for (int i = 0; i < 100_000; i++)
    {
      double x = (r.NextDouble() - 0.5) * Math.Pow(10, r.Next(-40, 40));
      float down = MeshNode.Down(x), up = MeshNode.Up(x);
      Assert.True(down <= x && up >= x && (down == up ? down == x : MathF.BitIncrement(down) == up), $"{x}: [{down}, {up}]");
    }
  }
}
