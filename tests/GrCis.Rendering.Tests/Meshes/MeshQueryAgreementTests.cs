using Scene3D;
using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Xunit;

namespace GrCis.Rendering.Tests.Meshes;

/// <summary>
/// Every mesh query against the answer of testing every triangle (<see cref="MeshTriangles"/>, the faithful path's search)
/// or of the mesh's own list (<see cref="TriangleMesh.Intersect"/>), bit for bit, on meshes with flat, axis-aligned,
/// degenerate and far-from-origin triangles and on rays built to meet them badly: through vertices and edge midpoints,
/// with zero direction components, starting on the surface or inside.
/// </summary>
public class MeshQueryAgreementTests
{
  public static TheoryData<string, int> Meshes => new()
  {
    { "torus", 3_000 },
    { "cube", 3_000 },
    { "awkward", 4_000 },
    { "awkward-far", 4_000 },    // the same triangles about 10⁶ from the origin
    { "torus-20k", 800 },
  };

  static SceneBrep Make(string name) => name switch
  {
    "torus" => ProceduralMesh.TorusWithTriangles(2_000),
    "torus-20k" => ProceduralMesh.TorusWithTriangles(20_000),
    "cube" => MeshTestSupport.Read(MeshTestSupport.CubeObj),
    "awkward" => Awkward(Vector3.Zero),
    _ => Awkward(new Vector3(1.0e6f, -2.0e6f, 5.0e5f)),
  };

  [Theory]
  [MemberData(nameof(Meshes))]
  public void Bvh_queries_find_what_testing_every_triangle_finds(string name, int rays)
  {
    SceneBrep mesh = Make(name);
    var bvh = new MeshBvh(mesh);
    var all = new MeshTriangles(mesh);
    var rnd = new Random(977);
    var hits = new List<MeshHit>();
    var listed = new List<MeshHit>();
    int answers = 0, blocked = 0, onlyBack = 0, ranged = 0, zoned = 0;
    foreach ((Vector3d o, Vector3d d) in Rays(mesh, all, rnd, rays))
    {
      double len2 = d.LengthSquared;
      hits.Clear();
      all.IntersectAll(o, d, hits);
      string ray = $"{name}: {o} + t{d}";

      // IntersectAll: the same hits.
      listed.Clear();
      bvh.IntersectAll(o, d, listed);
      Assert.True(hits.Count == listed.Count, $"{ray}: {hits.Count} hits by brute force, {listed.Count} by the BVH");
      hits.Sort(ByTThenTriangle);
      listed.Sort(ByTThenTriangle);
      for (int i = 0; i < hits.Count; i++)
        Same(hits[i], listed[i], ray);

      foreach (bool accepted in new[] { true, false })
      {
        bool expected = ListedHits.Nearest(hits, len2, accepted, out MeshHit want);
        Assert.True(expected == bvh.Nearest(o, d, len2, accepted, out MeshHit have), $"{ray}, accepted={accepted}");
        if (expected)
        {
          Same(want, have, ray);
          answers++;
        }
      }

      // Any, front faces only (the union's shadow walk): true with one of the accepted front hits up to tMax; false with
      // onlyBack when only back faces are there.
      double tMax = hits.Count > 0 && rnd.Next(3) > 0 ? hits[rnd.Next(hits.Count)].T : rnd.Next(2) == 0 ? double.PositiveInfinity : 2.0 * rnd.NextDouble();
      bool anyFront = false, anyBack = false;
      foreach (MeshHit h in hits)
        if (ListedHits.Accepted(h.T, len2) && h.T <= tMax)
          (h.Front ? ref anyFront : ref anyBack) = true;
      bool got = bvh.Any(o, d, len2, 0.0, tMax, true, out MeshHit any, out bool inZone, out bool back);
      Assert.False(inZone);
      Assert.True(anyFront == got, $"{ray}, tMax {tMax}: front hit {anyFront}, Any (front) {got}");
      if (got)
      {
        Assert.Contains(hits, h => h.T == any.T && h.Triangle == any.Triangle && h.U == any.U && h.V == any.V && h.Front);
        Assert.True(any.T <= tMax && ListedHits.Accepted(any.T, len2));
        blocked++;
      }
      else
      {
        Assert.True(anyBack == back, $"{ray}, tMax {tMax}: back hit {anyBack}, onlyBack {back}");
        onlyBack += back ? 1 : 0;
      }

      // Any with a zone (0, zone] that must be clear (a lone mesh's occlusion walk): stopped by an accepted hit there, else
      // true with one of the accepted hits (front faces, or either face) in (zone, tMax].
      double zone = Math.Min(tMax, hits.Count > 0 && rnd.Next(2) == 0 ? Math.Max(0.0, hits[rnd.Next(hits.Count)].T) : rnd.Next(2) == 0 ? 0.0 : TriangleMesh.Zone(bvh, d, len2));
      bool frontOnly = rnd.Next(2) == 0;
      bool zoneHit = hits.Exists(h => ListedHits.Accepted(h.T, len2) && h.T <= zone);
      bool inRange = hits.Exists(h => ListedHits.Accepted(h.T, len2) && h.T > zone && h.T <= tMax && (h.Front || !frontOnly));
      bool backInRange = hits.Exists(h => ListedHits.Accepted(h.T, len2) && h.T > zone && h.T <= tMax && !h.Front);
      got = bvh.Any(o, d, len2, zone, tMax, frontOnly, out any, out inZone, out back);
      string range = $"{ray}, zone {zone:R}, tMax {tMax:R}, front only {frontOnly}";
      Assert.True(zoneHit == inZone, $"{range}: zone hit {zoneHit}, Any says {inZone}");
      Assert.True(zoneHit ? !got : inRange == got, $"{range}: accepted hit in range {inRange}, Any {got}");
      if (got)
      {
        Assert.Contains(hits, h => h.T == any.T && h.Triangle == any.Triangle && h.U == any.U && h.V == any.V && h.Front == any.Front);
        Assert.True(any.T > zone && any.T <= tMax && ListedHits.Accepted(any.T, len2) && (any.Front || !frontOnly));
        ranged++;
      }
      else if (!zoneHit)
        Assert.True(back == (frontOnly && backInRange), $"{range}: back hit {backInRange}, onlyBack {back}");
      zoned += zoneHit ? 1 : 0;
    }
    Assert.True(answers > rays / 3, $"only {answers} answers with a hit: the rays miss the mesh");
    Assert.True(ranged > rays / 10 && zoned > rays / 20, $"{ranged} any-hits in a range, {zoned} in a zone");
    Assert.True(blocked > rays / 10 && onlyBack > 0, $"{blocked} any-hits, {onlyBack} back-only answers: the any-hit cases are not exercised");
  }

  [Theory]
  [MemberData(nameof(Meshes))]
  public void IntersectFirst_and_FirstRecord_answer_as_the_mesh_list(string name, int rays)
  {
    SceneBrep mesh = Make(name);
    var solid = new TriangleMesh(mesh);
    var all = new MeshTriangles(mesh);
    var rnd = new Random(31);
    int inside = 0, found = 0;
    foreach ((Vector3d o, Vector3d d) in Rays(mesh, all, rnd, rays))
    {
      double len2 = d.LengthSquared;
      bool want = FromList(solid.Intersect(o, d), len2, out SolidRecord w, out bool wantInside);
      bool got = solid.IntersectFirst(o, d, len2, out SolidRecord h, out bool gotInside);
      string ray = $"{name}: {o} + t{d}";
      Assert.True(want == got, $"{ray}: list {want}, IntersectFirst {got}");
      Assert.True(wantInside == gotInside, $"{ray}: inside before: list {wantInside}, IntersectFirst {gotInside}");
      if (want)
      {
        Assert.Equal(w.T, h.T);
        Assert.Equal(w.Data, h.Data);
        Assert.Equal(w.Aux, h.Aux);
        Assert.Equal(w.CoordLocal, h.CoordLocal);
        Assert.Equal(w.Enter, h.Enter);
        Assert.Equal(w.Front, h.Front);
        found++;
      }
      inside += wantInside ? 1 : 0;

      // The record alone (a scene of this one mesh): the same, up to a bound.
      double tMax = rnd.Next(2) == 0 ? double.PositiveInfinity : 3.0 * rnd.NextDouble();
      bool alone = ((IAnyHitSolid)solid).FirstRecord(o, d, len2, tMax, out SolidRecord r);
      Assert.True((want && w.T <= tMax) == alone, $"{ray}, tMax {tMax}: list {want} (T {w.T:R}), FirstRecord {alone}");
      if (alone)
        Assert.True(r.T.Equals(w.T) && r.Data == w.Data && r.Aux == w.Aux && r.CoordLocal == w.CoordLocal && r.Enter == w.Enter && r.Front == w.Front,
                    $"{ray}: FirstRecord T {r.T:R} #{r.Data}, list T {w.T:R} #{w.Data}");
    }
    Assert.True(found > rays / 4 && inside > rays / 50, $"{found} hits, {inside} rays starting inside: the cases are not exercised");
  }

  /// <summary>The first accepted record of a mesh's list and the list's state just before it (what IntersectFirst promises).</summary>
  static bool FromList(LinkedList<Intersection>? list, double len2, out SolidRecord hit, out bool insideBefore)
  {
    hit = default;
    insideBefore = false;
    if (list == null || list.First == null)
      return false;
    insideBefore = !list.First.Value.Enter;
    foreach (Intersection i in list)
    {
      if (ListedHits.Accepted(i.T, len2))
      {
        hit.T = i.T;
        hit.CoordLocal = i.CoordLocal;
        hit.Enter = i.Enter;
        hit.Front = i.Front;
        // The triangle and barycentrics, as the record carries them (HitData is the mesh's own).
        var data = i.SolidData!;
        hit.Data = (int)data.GetType().GetField("Face")!.GetValue(data)!;
        hit.Aux = new Vector3d((double)data.GetType().GetField("U")!.GetValue(data)!, (double)data.GetType().GetField("V")!.GetValue(data)!, 0.0);
        return true;
      }
      insideBefore = i.Enter;
    }
    return false;
  }

  static int ByTThenTriangle(MeshHit x, MeshHit y) => x.T != y.T ? x.T.CompareTo(y.T) : x.Triangle.CompareTo(y.Triangle);

  static void Same(in MeshHit want, in MeshHit have, string ray)
  {
    Assert.True(want.T.Equals(have.T) && want.Triangle == have.Triangle && want.U.Equals(have.U) && want.V.Equals(have.V) && want.Front == have.Front,
                $"{ray}: want T {want.T:R} #{want.Triangle} ({want.U:R}, {want.V:R}) {want.Front}, have T {have.T:R} #{have.Triangle} ({have.U:R}, {have.V:R}) {have.Front}");
  }

  /// <summary>
  /// Rays of several kinds, by turns: from outside or inside the mesh's box, towards a vertex or an edge's midpoint (exact
  /// grazing), along an axis or with one zero component, and from a hit point on the surface (the rejected hits matter).
  /// </summary>
  internal static IEnumerable<(Vector3d, Vector3d)> Rays(SceneBrep mesh, MeshTriangles all, Random rnd, int count)
  {
    Vector3d min = Vector3d.PositiveInfinity, max = Vector3d.NegativeInfinity;
    for (int i = 0; i < mesh.Vertices; i++)
    {
      min = Vector3d.ComponentMin(min, mesh.GetVertex(i));
      max = Vector3d.ComponentMax(max, mesh.GetVertex(i));
    }
    Vector3d center = 0.5 * (min + max), half = 0.5 * (max - min) + new Vector3d(0.5);
    var hits = new List<MeshHit>();
    for (int r = 0; r < count; r++)
    {
      Vector3d Uniform(double scale) => center + scale * new Vector3d(half.X * (2.0 * rnd.NextDouble() - 1.0), half.Y * (2.0 * rnd.NextDouble() - 1.0), half.Z * (2.0 * rnd.NextDouble() - 1.0));
      Vector3d Vertex() => mesh.GetVertex(rnd.Next(mesh.Vertices));
      Vector3d o = (r % 3) switch
      {
        0 => Uniform(0.9),                                                 // inside the box
        1 => Uniform(2.5),                                                 // mostly outside it
        _ => Vertex() + new Vector3d(0.0, 0.0, rnd.Next(2) == 0 ? 3.0 : -3.0),   // above a vertex, on its planes
      };
      Vector3d d;
      switch (r % 7)
      {
        case 0: d = new Vector3d(0.0, 0.0, o.Z > center.Z ? -1.0 : 1.0); break;   // along z: two 0 · ∞ slabs
        case 1: d = new Vector3d(2.0 * rnd.NextDouble() - 1.0, r % 14 == 1 ? -0.0 : 0.0, 2.0 * rnd.NextDouble() - 1.0); break;
        case 2: d = Vertex() - o; break;                                  // through a vertex
        case 3:
          mesh.GetTriangleVertices(rnd.Next(mesh.Triangles), out Vector3 a, out Vector3 b, out _);
          d = 0.5 * ((Vector3d)a + (Vector3d)b) - o;                      // through an edge's midpoint
          break;
        default: d = (0.5 + rnd.NextDouble()) * new Vector3d(2.0 * rnd.NextDouble() - 1.0, 2.0 * rnd.NextDouble() - 1.0, 2.0 * rnd.NextDouble() - 1.0); break;
      }
      if (d.LengthSquared == 0.0)
        d = Vector3d.UnitX;
      if (r % 5 == 4)
      {
        // Leave the surface from a hit point, in a new direction.
        hits.Clear();
        all.IntersectAll(o, d, hits);
        if (hits.Count > 0)
          o += hits[rnd.Next(hits.Count)].T * d;
        d = new Vector3d(2.0 * rnd.NextDouble() - 1.0, 2.0 * rnd.NextDouble() - 1.0, 2.0 * rnd.NextDouble() - 1.0);
      }
      yield return (o, d);
    }
  }

  /// <summary>
  /// Flat grids in the three axis planes (leaf boxes flat in x, y and z, crossing one another), triangles with a repeated
  /// vertex, collinear vertices or all three equal, slivers, and random triangles of all sizes; all moved by <paramref name="offset"/>.
  /// </summary>
  internal static SceneBrep Awkward(Vector3 offset)
  {
    var mesh = new SceneBrep();
    var rnd = new Random(5);
    int V(float x, float y, float z) => mesh.AddVertex(new Vector3(x, y, z) + offset);
    for (int axis = 0; axis < 3; axis++)
      for (int i = -3; i < 3; i++)
        for (int j = -3; j < 3; j++)
        {
          Vector3 P(float s, float t) => axis == 0 ? new Vector3(0f, s, t) : axis == 1 ? new Vector3(s, 0.5f, t) : new Vector3(s, t, -0.25f);
          Vector3 p00 = P(i, j), p10 = P(i + 1, j), p11 = P(i + 1, j + 1), p01 = P(i, j + 1);
          int a = V(p00.X, p00.Y, p00.Z), b = V(p10.X, p10.Y, p10.Z), c = V(p11.X, p11.Y, p11.Z), d = V(p01.X, p01.Y, p01.Z);
          // Both windings: front and back faces by turns.
          if (((i + j) & 1) == 0)
          {
            mesh.AddTriangle(a, b, c);
            mesh.AddTriangle(a, c, d);
          }
          else
          {
            mesh.AddTriangle(a, c, b);
            mesh.AddTriangle(a, d, c);
          }
        }
    for (int k = 0; k < 60; k++)
    {
      float x = rnd.Next(-3, 4), y = rnd.Next(-3, 4), z = rnd.Next(-3, 4);
      int a = V(x, y, z), b = V(x + 1f, y, z), c = V(x + 2f, y, z);
      mesh.AddTriangle(a, a, b);                                   // a repeated vertex
      mesh.AddTriangle(a, b, c);                                   // collinear
      mesh.AddTriangle(a, a, a);                                   // a point
      mesh.AddTriangle(a, V(x + 1e-3f, y + 1e-3f, z), V(x + 1f, y + 1f, z + 1e-6f));   // a sliver, nearly flat in z
    }
    for (int k = 0; k < 400; k++)
    {
      float s = k % 3 == 0 ? 0.01f : k % 3 == 1 ? 0.5f : 3f;
      float x = 6f * (float)rnd.NextDouble() - 3f, y = 6f * (float)rnd.NextDouble() - 3f, z = 6f * (float)rnd.NextDouble() - 3f;
      float R() => s * (2f * (float)rnd.NextDouble() - 1f);
      mesh.AddTriangle(V(x, y, z), V(x + R(), y + R(), z + R()), V(x + R(), y + R(), z + R()));
    }
    return mesh;
  }
}
