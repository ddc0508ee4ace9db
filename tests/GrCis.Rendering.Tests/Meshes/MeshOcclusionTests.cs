using Scene3D;
using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Xunit;

namespace GrCis.Rendering.Tests.Meshes;

/// <summary>
/// A lone mesh's shadow answer (<see cref="IAnyHitSolid.Occluded"/>, early exit in any order) against the exact ones: the
/// mesh's list (first accepted record, not far) and the ordered search (<see cref="IAnyHitSolid.FirstRecord"/>), on
/// closed, open and awkward meshes and on stacks of near-coincident faces whose duplicates chain across the zone where
/// the list may drop the first accepted hit. The steps of the proof are checked on every ray too.
/// </summary>
public class MeshOcclusionTests
{
  public static TheoryData<string, int> Meshes => new()
  {
    { "torus", 2_500 },
    { "open-torus", 2_500 },
    { "cube", 2_000 },
    { "awkward", 3_000 },
    { "awkward-far", 3_000 },
    { "chains", 6_000 },
  };

  static SceneBrep Make(string name) => name switch
  {
    "torus" => ProceduralMesh.TorusWithTriangles(2_000),
    "open-torus" => Open(ProceduralMesh.TorusWithTriangles(2_000)),
    "cube" => MeshTestSupport.Read(MeshTestSupport.CubeObj),
    "awkward" => MeshQueryAgreementTests.Awkward(Vector3.Zero),
    "awkward-far" => MeshQueryAgreementTests.Awkward(new Vector3(1.0e6f, -2.0e6f, 5.0e5f)),
    _ => Chains(),
  };

  [Theory]
  [MemberData(nameof(Meshes))]
  public void Occluded_answers_as_the_list_and_the_ordered_search(string name, int rays)
  {
    SceneBrep mesh = Make(name);
    var solid = new TriangleMesh(mesh);
    IAnyHitSolid any = solid;
    MeshBvh bvh = solid.Bvh;
    var all = new MeshTriangles(mesh);
    var rnd = new Random(4242);
    int blocked = 0, free = 0, early = 0, zoneHits = 0, dropped = 0;
    foreach ((Vector3d o, Vector3d ray) in name == "chains" ? ChainRays(rnd, rays) : MeshQueryAgreementTests.Rays(mesh, all, rnd, rays))
    {
      foreach (Vector3d d in Segments(o, ray, all, rnd))
      {
        double len2 = d.LengthSquared;
        string seg = $"{name}: {o} + t{d}";
        // The list: its first accepted record, blocking when it is not far (FirstRealIntersection, then not Far(1)).
        bool want = ListRecord(solid.Intersect(o, d), len2, out double wantT);
        var hits = new List<MeshHit>();
        all.IntersectAll(o, d, hits);
        bool hasFirst = ListedHits.Nearest(hits, len2, true, out MeshHit first);
        bool wasDropped = hasFirst && !(want && wantT.Equals(first.T));
        want = want && PreparedScene.NotFar(wantT, len2);
        // The ordered search (the path before the early exit).
        bool ordered = any.FirstRecord(o, d, len2, double.PositiveInfinity, out SolidRecord r) && PreparedScene.NotFar(r.T, len2);
        Assert.True(want == ordered, $"{seg}: list {want}, FirstRecord {ordered}");
        // Any valid bound: one just beyond "not far" (as the prepared scene passes), a loose one, none.
        double bound = 1.0 + 1.05 * Intersection.RAY_EPSILON / Math.Sqrt(len2);
        foreach (double tMax in new[] { bound, 2.0 * bound, double.PositiveInfinity })
          Assert.True(want == any.Occluded(o, d, len2, tMax), $"{seg}, tMax {tMax:R}: list {want}, Occluded {!want}");
        (want ? ref blocked : ref free)++;
        dropped += wasDropped ? 1 : 0;

        // The proof's steps: an accepted hit H beyond the zone with none in the zone makes the first accepted hit the
        // record, no later than H; none found means no accepted hit at all.
        double zone = TriangleMesh.Zone(bvh, d, len2);
        bool got = bvh.Any(o, d, len2, zone, double.PositiveInfinity, false, out MeshHit h, out bool inZone, out _);
        Assert.True(inZone == hits.Exists(x => ListedHits.Accepted(x.T, len2) && x.T <= zone), $"{seg}: zone {zone:R}, Any says {inZone}");
        zoneHits += inZone ? 1 : 0;
        if (got)
        {
          Assert.True(hasFirst && first.T > zone && first.T <= h.T, $"{seg}: first accepted T {first.T:R}, zone {zone:R}, H {h.T:R}");
          Assert.False(wasDropped, $"{seg}: the record is not the first accepted hit");
          early += PreparedScene.NotFar(h.T, len2) ? 1 : 0;
        }
        else if (!inZone)
          Assert.False(hasFirst, $"{seg}: no hit found, first accepted T {first.T:R}");
      }
    }
    Assert.True(blocked > rays / 5 && free > rays / 5 && early > rays / 10, $"{blocked} blocked, {free} free, {early} early exits");
    if (name == "chains")
      Assert.True(zoneHits > rays / 10 && dropped > rays / 20, $"{zoneHits} zone hits, {dropped} first accepted hits dropped: the chains are not exercised");
  }

  [Theory]
  [InlineData("torus")]
  [InlineData("open-torus")]
  [InlineData("chains")]
  public void A_scene_of_one_mesh_shadows_as_the_lists(string name)
  {
    // One mesh under a transform (a union of one child is the child's list): PreparedScene.OccludedSingle.
    var root = new CSGInnerNode(SetOperation.Union);
    root.InsertChild(new TriangleMesh(Make(name)), Matrix4d.Scale(1.0, 0.9, 1.1) * Matrix4d.RotateY(0.3) * Matrix4d.CreateTranslation(0.1, -0.2, 0.3));
    PreparedScene ps = PreparedScene.Prepare(root);
    Assert.Equal(1, ps.MemberCount);
    var lists = new SceneLists(root);
    var rnd = new Random(name.Length * 131);
    int blocked = 0, free = 0;
    for (int n = 0; n < 4000; n++)
    {
      Vector3d a = Point(rnd, name), b = Point(rnd, name);
      // From a surface point (a shadow ray's start) now and then.
      if (n % 2 == 0 && lists.FirstHit(a, b - a) is Intersection start)
        a = start.CoordWorld;
      Vector3d dir = b - a;
      if (dir.LengthSquared == 0.0)
        continue;
      bool expected = lists.AnyHit(a, dir);
      Assert.True(expected == ps.AnyHit(a, dir), $"{name}: segment {n} from {a} along {dir}: lists say {(expected ? "blocked" : "free")}");
      (expected ? ref blocked : ref free)++;
    }
    // The stacks are small in their box: fewer segments meet them.
    Assert.True(blocked > (name == "chains" ? 100 : 400) && free > 400, $"{blocked} blocked, {free} free");
  }

  /// <summary>A random point around the mesh (the stacks of <see cref="Chains"/> lie in x ∈ [0, 8], y ∈ [0, 3]).</summary>
  static Vector3d Point(Random r, string name) => name == "chains"
    ? new(8.0 * r.NextDouble(), 3.0 * r.NextDouble(), 2.0 * r.NextDouble() - 1.0)
    : new(4.0 * r.NextDouble() - 2.0, 4.0 * r.NextDouble() - 2.0, 4.0 * r.NextDouble() - 2.0);

  /// <summary>
  /// Segments along a ray: as given, ending at one of its hits (T = 1 there, the edge of "not far"), just short of or
  /// beyond it by a few RAY_EPSILON, and of a random length.
  /// </summary>
  static IEnumerable<Vector3d> Segments(Vector3d o, Vector3d d, MeshTriangles all, Random rnd)
  {
    yield return d;
    var hits = new List<MeshHit>();
    all.IntersectAll(o, d, hits);
    hits.RemoveAll(h => !(h.T > 0.0));
    if (hits.Count > 0)
    {
      double t = hits[rnd.Next(hits.Count)].T;
      yield return t * d;
      double shift = (rnd.NextDouble() * 4.0 - 2.0) * Intersection.RAY_EPSILON / d.Length;
      if (t + shift > 0.0)
        yield return (t + shift) * d;
    }
    yield return (0.05 + 2.0 * rnd.NextDouble()) * d;
  }

  /// <summary>The first accepted record's T in a mesh's list.</summary>
  static bool ListRecord(LinkedList<Intersection>? list, double len2, out double t)
  {
    t = 0.0;
    if (list == null)
      return false;
    foreach (Intersection i in list)
      if (ListedHits.Accepted(i.T, len2))
      {
        t = i.T;
        return true;
      }
    return false;
  }

  /// <summary>The mesh with every third triangle left out: lists that start inside, exits while outside.</summary>
  static SceneBrep Open(SceneBrep full)
  {
    var mesh = new SceneBrep();
    for (int v = 0; v < full.Vertices; v++)
      mesh.AddVertex(full.GetVertex(v));
    for (int t = 0; t < full.Triangles; t++)
      if (t % 3 != 0)
      {
        full.GetTriangleVertices(t, out int a, out int b, out int c);
        mesh.AddTriangle(a, b, c);
      }
    return mesh;
  }

  /// <summary>
  /// Stacks of unit squares in planes z = c, a little apart (far less than the duplicate tolerance for the chain rays),
  /// the same winding in a stack (so their hits chain as duplicates) but for the stack whose middle square is turned;
  /// stacks at several heights around 0, which the chain rays start from, and a far vertex that sets the mesh's extent
  /// (hence the tolerance). Opposite squares at z = ±0.5 give blockers beyond the zone.
  /// </summary>
  static SceneBrep Chains()
  {
    var mesh = new SceneBrep();
    void Square(float x, float y, float z, bool turned)
    {
      int a = mesh.AddVertex(new Vector3(x, y, z)), b = mesh.AddVertex(new Vector3(x + 1f, y, z));
      int c = mesh.AddVertex(new Vector3(x + 1f, y + 1f, z)), e = mesh.AddVertex(new Vector3(x, y + 1f, z));
      if (turned)
      {
        mesh.AddTriangle(a, c, b);
        mesh.AddTriangle(a, e, c);
      }
      else
      {
        mesh.AddTriangle(a, b, c);
        mesh.AddTriangle(a, c, e);
      }
    }
    // Extent about 1e4: the tolerance is 1e-6 / |d| against the rejected hits' limit 1e-4 / |d|.
    int f = mesh.AddVertex(new Vector3(5000f, 5000f, 5000f));
    mesh.AddTriangle(f, mesh.AddVertex(new Vector3(5000f, 5001f, 5000f)), mesh.AddVertex(new Vector3(5001f, 5000f, 5000f)));
    for (int stack = 0; stack < 4; stack++)
      for (int k = -6; k <= 10; k++)
      {
        // Spacing 0.4e-6 (x, |d| up to 2): 0.2e-6 at most between hits, within the tolerance.
        float z = (float)(1.0e-4 * (stack + 1) + 0.4e-6 * k);
        Square(2f * stack, 0f, z, stack == 3 && k == 2);
        Square(2f * stack, 0f, -z, stack == 2);
      }
    Square(0f, 2f, 0.5f, false);
    Square(0f, 2f, -0.5f, true);
    return mesh;
  }

  /// <summary>Rays from near z = 0 across the stacks (up, down, slightly tilted, of lengths that move the zone).</summary>
  static IEnumerable<(Vector3d, Vector3d)> ChainRays(Random rnd, int count)
  {
    for (int r = 0; r < count; r++)
    {
      int stack = rnd.Next(4);
      double x = 2.0 * stack + 0.05 + 0.9 * rnd.NextDouble(), y = 0.05 + 0.9 * rnd.NextDouble();
      // Start at, below or above zero by up to a few tolerances, and sometimes inside a stack.
      double z = (rnd.Next(3) - 1) * rnd.NextDouble() * 4.0e-6 + (r % 5 == 0 ? 1.0e-4 * (stack + 1) * (rnd.Next(2) == 0 ? 1 : -1) : 0.0);
      double length = new[] { 1.0, 0.5, 2.0, 1.0 + rnd.NextDouble(), 0.7 + 0.6 * rnd.NextDouble() }[r % 5];
      double tilt = rnd.Next(3) == 0 ? 0.0 : 1e-3 * (2.0 * rnd.NextDouble() - 1.0);
      var d = new Vector3d(tilt, tilt * 0.5, rnd.Next(2) == 0 ? length : -length);
      if (r % 7 == 3)
        (x, y, d) = (0.05 + 0.9 * rnd.NextDouble(), 2.05 + 0.9 * rnd.NextDouble(), new Vector3d(0.0, 0.0, (rnd.Next(2) == 0 ? 1 : -1) * length));
      yield return (new Vector3d(x, y, z), d);
    }
  }
}
