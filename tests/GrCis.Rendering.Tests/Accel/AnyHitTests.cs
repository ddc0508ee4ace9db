using System;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Scene3D;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>
/// Shadow queries that stop at the first blocker and never look past the segment's end (the mesh's any-hit walk,
/// <see cref="IAnyHitSolid.IntersectAny"/>): on many seeded random segments against each solid kind the prepared scene
/// handles, and against closed, open and inward-facing meshes, the answer is the closest hit's within the segment.
/// </summary>
public class AnyHitTests
{
  /// <summary>A student's mesh that only names itself: it changes nothing of the library's.</summary>
  sealed class NamedMesh(SceneBrep m) : TriangleMesh(m);

  /// <summary>A student's mesh with records of its own: its shadow queries must ask them, not the library's walk.</summary>
  sealed class OwnRecordsMesh(SceneBrep m) : TriangleMesh(m)
  {
    public override bool IntersectFirst(in Vector3d p0, in Vector3d p1, double len2, out SolidRecord hit, out bool insideBefore) =>
      base.IntersectFirst(p0, p1, len2, out hit, out insideBefore);
  }

  [Fact]
  public void The_any_hit_walk_is_taken_for_the_library_mesh_and_subclasses_that_change_nothing_of_it()
  {
    SceneBrep torus = ProceduralMesh.Torus(12, 6);
    Assert.Equal(DirectSolid.AnyHit, LibraryTypes.DirectKernel(new TriangleMesh(torus)));
    Assert.Equal(DirectSolid.AnyHit, LibraryTypes.DirectKernel(new NamedMesh(torus)));
    Assert.Equal(DirectSolid.None, LibraryTypes.DirectKernel(new OwnRecordsMesh(torus)));
    Assert.Equal(DirectSolid.Sphere, LibraryTypes.DirectKernel(new Sphere()));
    Assert.Equal(DirectSolid.None, LibraryTypes.DirectKernel(new Cube()));
  }

  /// <summary>A torus mesh with every third triangle left out (open: lists that start inside, exits while outside).</summary>
  static SceneBrep OpenTorus(bool flipped = false)
  {
    SceneBrep full = ProceduralMesh.Torus(24, 12);
    var mesh = new SceneBrep();
    for (int v = 0; v < full.Vertices; v++)
      mesh.AddVertex(full.GetVertex(v));
    for (int t = 0; t < full.Triangles; t++)
    {
      if (!flipped && t % 3 == 0)
        continue;
      full.GetTriangleVertices(t, out int a, out int b, out int c);
      if (flipped)
        mesh.AddTriangle(a, c, b);
      else
        mesh.AddTriangle(a, b, c);
    }
    return mesh;
  }

  static ISceneNode Make(string kind) => kind switch
  {
    "sphere" => new Sphere(),
    "cube" => new Cube(),
    "cylinder" => new Cylinder(-1.0, 1.0),
    "torus" => new Torus(1.0, 0.4),
    "rectangle" => new Plane(-1.0, 1.0, -1.0, 1.0),
    "csg-difference" => Difference(),
    "mesh-closed" => new TriangleMesh(ProceduralMesh.Torus(30, 16)),
    "mesh-open" => new TriangleMesh(OpenTorus()),
    "mesh-inward" => new TriangleMesh(OpenTorus(flipped: true)),
    _ => throw new ArgumentException(kind),
  };

  static CSGInnerNode Difference()
  {
    var d = new CSGInnerNode(SetOperation.Difference);
    d.InsertChild(new Cube(), Matrix4d.Identity);
    d.InsertChild(new Sphere(), Matrix4d.Scale(0.7) * Matrix4d.CreateTranslation(0.5, 0.5, 0.0));
    return d;
  }

  public static TheoryData<string> Kinds() => new()
  {
    "sphere", "cube", "cylinder", "torus", "rectangle", "csg-difference", "mesh-closed", "mesh-open", "mesh-inward",
  };

  [Theory]
  [MemberData(nameof(Kinds))]
  public void Shadow_segments_against_each_solid_kind_answer_as_the_closest_hit_within_the_segment(string kind)
  {
    // Three of the kind under rotations and uneven scales (two overlapping), a floor rectangle and a ball.
    var r = new Random(kind.GetHashCode(StringComparison.Ordinal) & 0xffff);
    var root = new CSGInnerNode(SetOperation.Union);
    root.InsertChild(Make(kind), Matrix4d.Scale(1.0, 0.8, 1.2) * Matrix4d.RotateX(0.4) * Matrix4d.CreateTranslation(-0.8, 0.0, 0.0));
    root.InsertChild(Make(kind), Matrix4d.RotateY(1.1) * Matrix4d.CreateTranslation(0.2, 0.3, 0.4));
    root.InsertChild(Make(kind), Matrix4d.Scale(0.6) * Matrix4d.CreateTranslation(1.8, -0.5, -1.0));
    root.InsertChild(new Plane(-4, 4, -4, 4), Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0, -1.5, 0));
    root.InsertChild(new Sphere(), Matrix4d.Scale(0.5) * Matrix4d.CreateTranslation(0.0, 1.8, 0.0));
    PreparedScene ps = PreparedScene.Prepare(root);
    Assert.True(ps.StopsAtFirstBlocker);
    var lists = new SceneLists(root);

    int blocked = 0, free = 0;
    for (int n = 0; n < 6000; n++)
    {
      Vector3d a = Point(r, 3.0), b = Point(r, 3.0);
      // From a surface point (a shadow ray's start), and segments ending on a surface or just short of it.
      if (n % 3 != 0 && lists.FirstHit(a, b - a) is Intersection start)
      {
        Vector3d onSurface = start.CoordWorld;
        switch (n % 6)
        {
          case 1: a = onSurface; break;
          case 2: b = onSurface; break;
          case 4: b = onSurface - (b - a).Normalized() * (r.NextDouble() * 3.0 * Intersection.RAY_EPSILON); break;
          case 5: a = onSurface; b = Point(r, 0.5) + new Vector3d(0.0, 4.0, 0.0); break;
        }
      }
      Vector3d dir = b - a;
      if (dir.LengthSquared == 0.0)
        continue;
      bool expected = lists.AnyHit(a, dir);
      Assert.True(expected == ps.AnyHit(a, dir), $"{kind}: segment {n} from {a} along {dir}: lists say {(expected ? "blocked" : "free")}");
      if (expected)
        blocked++;
      else
        free++;
    }
    Assert.True(blocked > 800 && free > 800, $"{blocked} blocked, {free} free");
  }

  [Theory]
  [InlineData("mesh-closed")]
  [InlineData("mesh-open")]
  [InlineData("mesh-inward")]
  public void Mesh_any_hit_finds_a_blocker_whenever_the_closest_hit_in_the_segment_is_one(string kind)
  {
    var mesh = (TriangleMesh)Make(kind);
    var r = new Random(kind.Length * 7919);
    int blockers = 0, onlyAny = 0, early = 0;
    for (int n = 0; n < 20000; n++)
    {
      Vector3d p0 = Point(r, 1.6), p1 = Point(r, 1.6) - p0;
      if (n % 2 == 1 && mesh.IntersectFirst(p0, p1, p1.LengthSquared, out SolidRecord s, out _))
      {
        p0 += s.T * p1;   // from the surface, as a shadow ray
        p1 = Point(r, 2.0) - p0;
      }
      double len2 = p1.LengthSquared;
      double tMax = r.NextDouble() < 0.2 ? 0.3 + r.NextDouble() : 1.0;
      bool first = mesh.IntersectFirst(p0, p1, len2, out SolidRecord f, out bool insideFirst);
      bool any = ((IAnyHitSolid)mesh).IntersectAny(p0, p1, len2, tMax, out SolidRecord h, out bool insideAny);
      Assert.Equal(insideFirst, insideAny);
      bool firstBlocks = first && f.Enter && !insideFirst && f.T <= tMax;
      bool anyBlocks = any && h.Enter && !insideAny && h.T <= tMax;
      // The closest hit within the segment blocks ⇒ the any-hit walk finds a blocker (maybe another, never beyond tMax).
      if (firstBlocks)
      {
        Assert.True(anyBlocks, $"{kind}: ray {n}: the closest hit at t = {f.T} blocks, the any-hit walk found none");
        blocks(ref blockers, h.T != f.T, ref early);
      }
      else if (anyBlocks)
      {
        // Only where the closest record is an exit while outside (the list decides then) or beyond the bound.
        Assert.True(first && (!f.Enter || f.T > tMax), $"{kind}: ray {n}: any-hit blocker at t = {h.T} but the closest record is at {f.T}, Enter {f.Enter}");
        onlyAny++;
      }
      else if (any && insideAny == false && !h.Enter)
        Assert.True(first && !f.Enter, $"{kind}: ray {n}: an exit reported while outside, the closest record is an entry");
      if (anyBlocks)
        Assert.True(h.T > 0.0 && h.T * h.T * len2 > Intersection.RAY_EPSILON2 && h.T <= tMax);
    }
    Assert.True(blockers > 2000, $"{blockers} blocked");
    // The walk stops at the first blocker it meets, which need not be the closest.
    if (kind == "mesh-closed")
      Assert.True(early > 0, $"{early} any-hits that were not the closest, {onlyAny} where only the any-hit walk blocks");

    static void blocks(ref int count, bool notClosest, ref int early)
    {
      count++;
      if (notClosest)
        early++;
    }
  }

  static Vector3d Point(Random r, double half) =>
    new(half * (2.0 * r.NextDouble() - 1.0), half * (2.0 * r.NextDouble() - 1.0), half * (2.0 * r.NextDouble() - 1.0));
}
