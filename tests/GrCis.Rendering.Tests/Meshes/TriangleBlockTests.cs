using System;
using System.Runtime.Intrinsics;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Meshes;

/// <summary>
/// The float-vertex triangle blocks: four lanes tested at once give, lane for lane, the hits and the bits of the one-by-one
/// test on the stored doubles (<see cref="MeshTriangles"/>), over many scales, far from the origin, through vertices and
/// edges, along the axes; unused lanes never hit; each lane keeps its triangle handle.
/// </summary>
public class TriangleBlockTests
{
  static readonly double[] Scales = { 1e-20, 1e-6, 1e-3, 1.0, 1e3, 1e6, 1e20 };

  static Vector3 Point(Random r, Vector3d c, double s) =>
    (Vector3)(c + s * new Vector3d(r.NextDouble() * 2 - 1, r.NextDouble() * 2 - 1, r.NextDouble() * 2 - 1));

  [Fact]
  public void Block_test_matches_the_one_by_one_test_bit_for_bit()
  {
    var r = new Random(20261206);
    var tri = new double[9];
    var a = new Vector3[TriangleBlock.Width];
    var b = new Vector3[TriangleBlock.Width];
    var c = new Vector3[TriangleBlock.Width];
    int hits = 0, onFeature = 0;
    for (int n = 0; n < 50_000; n++)
    {
      double s = Scales[r.Next(Scales.Length)];
      Vector3d centre = r.Next(3) == 0 ? new Vector3d(1e5 * s, -2e4 * s, 3e5 * s) : Vector3d.Zero;
      var block = new TriangleBlock();
      block.Clear();
      int lanes = 1 + r.Next(TriangleBlock.Width);
      for (int l = 0; l < lanes; l++)
      {
        a[l] = Point(r, centre, s);
        b[l] = r.Next(16) == 0 ? a[l] : Point(r, centre, s);   // sometimes degenerate
        c[l] = r.Next(16) == 0 ? b[l] : Point(r, centre, s);
        block.Set(l, 1000 + l, a[l], b[l], c[l]);
      }
      // Aimed at a lane's vertex, edge or interior, from near or far, sometimes along an axis.
      int aim = r.Next(lanes);
      double wu = r.NextDouble(), wv = r.NextDouble() * (1 - wu);
      switch (r.Next(4))
      {
        case 0: wu = r.Next(2); wv = wu == 0 ? r.Next(2) : 0; onFeature++; break;   // a vertex
        case 1: wv = 1 - wu; onFeature++; break;                                      // the edge b–c
        case 2: wv = 0; onFeature++; break;                                           // the edge a–b
      }
      Vector3d va = (Vector3d)a[aim], vb = (Vector3d)b[aim], vc = (Vector3d)c[aim];
      Vector3d target = va + wu * (vb - va) + wv * (vc - va);
      Vector3d dir = r.Next(5) == 0
        ? (r.Next(3) switch { 0 => Vector3d.UnitX, 1 => Vector3d.UnitY, _ => Vector3d.UnitZ }) * (r.Next(2) == 0 ? s : -s)
        : s * new Vector3d(r.NextDouble() - 0.5, r.NextDouble() - 0.5, r.NextDouble() - 0.5);
      Vector3d o = target - (r.Next(2) == 0 ? 1.0 : 1e4 * r.NextDouble()) * dir;

      int mask = block.Hit(Vector256.Create(o.X), Vector256.Create(o.Y), Vector256.Create(o.Z),
                           Vector256.Create(dir.X), Vector256.Create(dir.Y), Vector256.Create(dir.Z),
                           out Vector256<double> t, out Vector256<double> u, out Vector256<double> v, out Vector256<double> det);
      for (int l = 0; l < TriangleBlock.Width; l++)
      {
        bool blockHit = (mask >> l & 1) != 0;
        if (l >= lanes)
        {
          Assert.False(blockHit);
          Assert.Equal(-1, block.Id[l]);
          continue;
        }
        Assert.Equal(1000 + l, block.Id[l]);
        MeshTriangles.Store(tri, 0, (Vector3d)a[l], (Vector3d)b[l], (Vector3d)c[l]);
        bool one = MeshTriangles.Hit(tri, 0, o.X, o.Y, o.Z, dir.X, dir.Y, dir.Z, out double t1, out double u1, out double v1, out bool front);
        Assert.Equal(one, blockHit);
        if (!one)
          continue;
        hits++;
        Assert.Equal(BitConverter.DoubleToInt64Bits(t1), BitConverter.DoubleToInt64Bits(t.GetElement(l)));
        Assert.Equal(BitConverter.DoubleToInt64Bits(u1), BitConverter.DoubleToInt64Bits(u.GetElement(l)));
        Assert.Equal(BitConverter.DoubleToInt64Bits(v1), BitConverter.DoubleToInt64Bits(v.GetElement(l)));
        Assert.Equal(front, det.GetElement(l) > 0.0);
      }
    }
    // The aimed lane is hit in most cases (not every one: rounding on edges and vertices, degenerate triangles).
    Assert.True(hits > 30_000, $"only {hits} hits");
    Assert.True(onFeature > 30_000);
  }

  [Fact]
  public void Each_triangle_s_vertices_come_back_from_its_block_as_the_mesh_s()
  {
    foreach (Scene3D.SceneBrep mesh in new[] { ProceduralMesh.Torus(40, 30), ProceduralMesh.Torus(3, 3, 1e6, 1e-3), ProceduralMesh.Torus(300, 200) })
    {
      var bvh = new MeshBvh(mesh);
      for (int tri = 0; tri < mesh.Triangles; tri++)
      {
        mesh.GetTriangleVertices(tri, out Vector3 a, out Vector3 b, out Vector3 c);
        bvh.Vertices(tri, out Vector3d va, out Vector3d vb, out Vector3d vc);
        Assert.Equal((Vector3d)a, va);
        Assert.Equal((Vector3d)b, vb);
        Assert.Equal((Vector3d)c, vc);
      }
      // Blocks are 160 bytes from a cache line on: each spans three lines (the prefetch covers three).
      Assert.Equal(0, bvh.FirstBlockLineOffset);
      Assert.Equal(160, System.Runtime.CompilerServices.Unsafe.SizeOf<TriangleBlock>());
    }
  }

  [Fact]
  public void Cleared_block_never_hits()
  {
    var block = new TriangleBlock();
    block.Clear();
    var rnd = new Random(7);
    for (int n = 0; n < 1000; n++)
    {
      Vector256<double> Any() => Vector256.Create(rnd.NextDouble() * 2 - 1);
      Assert.Equal(0, block.Hit(Any(), Any(), Any(), Any(), Any(), Any(), out _, out _, out _, out _));
    }
  }
}
