using Scene3D;
using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Xunit;

namespace GrCis.Rendering.Tests.Meshes;

/// <summary>
/// <see cref="MeshBvh.Nearest"/> (four padded child boxes per SIMD step, on the collapsed tree) against every triangle tested by brute
/// force: the same first accepted and last rejected hit, bit for bit, on rays built to stress the box test —
/// axis-parallel directions (0 · ∞ slabs), origins on the boxes' planes, flat boxes, rays leaving the surface.
/// </summary>
public class MeshBvhNearestTests
{
  [Theory]
  [InlineData("torus", 6_000)]
  [InlineData("cube", 6_000)]
  [InlineData("grid", 6_000)]
  [InlineData("torus-20k", 1_500)]   // a deeper tree: several levels of four-wide nodes
  public void Nearest_finds_what_testing_every_triangle_finds(string name, int rays)
  {
    SceneBrep mesh = name switch
    {
      "torus" => ProceduralMesh.TorusWithTriangles(2_000),
      "torus-20k" => ProceduralMesh.TorusWithTriangles(20_000),
      "cube" => MeshTestSupport.Read(MeshTestSupport.CubeObj),
      _ => Grid(12),
    };
    var bvh = new MeshBvh(mesh);
    var all = new MeshTriangles(mesh);
    var rnd = new Random(4242);
    var hits = new List<MeshHit>();
    var vertices = new List<Vector3d>();
    for (int i = 0; i < mesh.Vertices; i++)
      vertices.Add((Vector3d)mesh.GetVertex(i));

    int checkedRays = 0, withHits = 0;
    for (int r = 0; r < rays; r++)
    {
      Vector3d o = Origin(rnd, vertices, r);
      Vector3d d = Direction(rnd, r);
      if (r % 5 == 4)
      {
        // Leave the surface: start at a hit point of a random ray (the rejected query then matters).
        hits.Clear();
        all.IntersectAll(o, d, hits);
        if (hits.Count > 0)
          o += hits[rnd.Next(hits.Count)].T * d;
        d = Direction(rnd, r + 1);
      }
      double len2 = d.LengthSquared;
      hits.Clear();
      all.IntersectAll(o, d, hits);
      foreach (bool accepted in new[] { true, false })
      {
        bool expected = ListedHits.Nearest(hits, len2, accepted, out MeshHit want);
        bool got = bvh.Nearest(o, d, len2, accepted, out MeshHit have);
        Assert.True(expected == got, $"{name} ray {r} ({o} + t{d}), accepted={accepted}: brute force {expected}, BVH {got}");
        if (expected)
        {
          Assert.Equal(want.T, have.T);
          Assert.Equal(want.Triangle, have.Triangle);
          Assert.Equal(want.U, have.U);
          Assert.Equal(want.V, have.V);
          Assert.Equal(want.Front, have.Front);
          withHits++;
        }
      }
      checkedRays++;
    }
    Assert.Equal(rays, checkedRays);
    Assert.True(withHits > rays / 6, $"only {withHits} answers with a hit: the rays miss the mesh");
  }

  static Vector3d Origin(Random rnd, List<Vector3d> vertices, int r) => (r % 3) switch
  {
    // Exactly on the planes of vertices (and so of leaf boxes), or near the mesh.
    0 => vertices[rnd.Next(vertices.Count)] + new Vector3d(0.0, 0.0, rnd.Next(2) == 0 ? 3.0 : -3.0),
    1 => new Vector3d(vertices[rnd.Next(vertices.Count)].X, vertices[rnd.Next(vertices.Count)].Y, 4.0 * rnd.NextDouble() - 2.0),
    _ => new Vector3d(6.0 * rnd.NextDouble() - 3.0, 6.0 * rnd.NextDouble() - 3.0, 6.0 * rnd.NextDouble() - 3.0),
  };

  static Vector3d Direction(Random rnd, int r)
  {
    Vector3d d = new(2.0 * rnd.NextDouble() - 1.0, 2.0 * rnd.NextDouble() - 1.0, 2.0 * rnd.NextDouble() - 1.0);
    switch (r % 4)
    {
      case 0: return new Vector3d(0.0, 0.0, d.Z < 0 ? -1.0 : 1.0);        // along z: two 0 · ∞ axes
      case 1: return new Vector3d(d.X, r % 8 == 1 ? -0.0 : 0.0, d.Z);     // one zero component (±0)
      default: return d * (0.5 + rnd.NextDouble());                         // not unit length
    }
  }

  /// <summary>An n×n grid of unit squares in the plane z = 0 (every leaf box is flat in z).</summary>
  static SceneBrep Grid(int n)
  {
    var mesh = new SceneBrep();
    for (int y = 0; y <= n; y++)
      for (int x = 0; x <= n; x++)
        mesh.AddVertex(new Vector3((float)(x - n / 2), (float)(y - n / 2), 0f));
    for (int y = 0; y < n; y++)
      for (int x = 0; x < n; x++)
      {
        int a = y * (n + 1) + x;
        mesh.AddTriangle(a, a + 1, a + n + 2);
        mesh.AddTriangle(a, a + n + 2, a + n + 1);
      }
    return mesh;
  }
}
