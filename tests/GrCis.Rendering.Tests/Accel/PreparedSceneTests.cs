using System;
using System.Collections.Generic;
using GrCis.Testing;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;

namespace GrCis.Rendering.Tests.Accel;

public class PreparedSceneTests
{
  [Fact]
  public void Nested_unions_are_flattened_into_bvh_members()
  {
    IRayScene scene = TestScenes.Flake9(2);
    PreparedScene ps = PreparedScene.Prepare(scene.Intersectable);
    Assert.Equal(global::Rendering.Scenes.SphereFlake9Count(2) + 1, ps.MemberCount);
    Assert.Equal(global::Rendering.Scenes.SphereFlake9Count(2), ps.BoundedCount);
    Assert.Equal(1, ps.UnboundedCount); // the floor plane
    Assert.Equal(0, ps.ListMemberCount);
  }

  [Fact]
  public void Non_union_csg_and_script_solids_are_list_members()
  {
    PreparedScene ps = PreparedScene.Prepare(TestScenes.CsgMix().Intersectable);
    // difference, intersection and the script sphere answer through the LinkedList API.
    Assert.Equal(3, ps.ListMemberCount);
    // the script sphere and the plane are tested for every ray; CSG of known closed solids is bounded.
    Assert.Equal(2, ps.UnboundedCount);
  }

  [Fact]
  public void Equal_t_hits_resolve_to_the_first_child_like_the_union_merge()
  {
    // Two identical spheres: the merge keeps the left (first) child's record.
    var root = new CSGInnerNode(SetOperation.Union);
    var a = new RefSphere();
    var b = new RefSphere();
    root.InsertChild(a, Matrix4d.Identity);
    root.InsertChild(b, Matrix4d.Identity);
    PreparedScene ps = PreparedScene.Prepare(root);
    var p0 = new Vector3d(0, 0, -5);
    var p1 = new Vector3d(0, 0, 1);
    Intersection? faithful = Intersection.FirstIntersection(root.Intersect(p0, p1), ref p1);
    Intersection? fast = ps.FirstHit(p0, p1);
    Assert.Same(a, faithful!.Solid);
    Assert.Same(a, fast!.Solid);
    Assert.Equal(faithful.T, fast.T);
  }

  [Fact]
  public void Ray_starting_inside_a_member_takes_the_faithful_answer()
  {
    // Inside the big sphere the union hides the small one: the first record is the big sphere's exit.
    var root = new CSGInnerNode(SetOperation.Union);
    var big = new RefSphere();
    var small = new RefSphere();
    root.InsertChild(big, Matrix4d.Scale(10));
    root.InsertChild(small, Matrix4d.Identity);
    PreparedScene ps = PreparedScene.Prepare(root);
    var p0 = new Vector3d(0, 0, -5);
    var p1 = new Vector3d(0, 0, 1);
    Intersection? hit = ps.FirstHit(p0, p1);
    Assert.Same(big, hit!.Solid);
    Assert.Equal(15.0, hit.T, 12);
    Assert.Equal(1, ps.FallbackCount);
  }

  [Fact]
  public void Shadow_query_ignores_no_shadow_blockers_and_hits_beyond_the_light()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    var ghost = new RefSphere();
    ghost.SetAttribute(PropertyName.NO_SHADOW, true);
    root.InsertChild(ghost, Matrix4d.CreateTranslation(0, 0, 2));
    root.InsertChild(new RefSphere(), Matrix4d.CreateTranslation(0, 0, 10));
    PreparedScene ps = PreparedScene.Prepare(root);
    var p0 = new Vector3d(0, 0, -3);
    Assert.False(ps.Occluded(p0, new Vector3d(0, 0, 6)));  // only the NO_SHADOW sphere before the light
    Assert.True(ps.Occluded(p0, new Vector3d(0, 0, 14)));  // the real sphere at z 9..11 blocks a light at z 11
    Assert.False(ps.Occluded(p0, new Vector3d(0, 0, 11.5))); // light before the real sphere
  }

  [Fact]
  public void Bounded_planes_skipped_by_their_line_box_answer_as_the_lists_do()
  {
    // Rectangles and triangles (open members, tested for every ray unless the whole line misses their box),
    // placed by random rotations and scales, beside a sphere; rays from anywhere, also from behind the planes
    // (where the union's inside state comes from records at negative t) and aimed at the planes' corners.
    var r = new Random(5);
    var root = new CSGInnerNode(SetOperation.Union);
    var corners = new List<Vector3d>();
    for (int k = 0; k < 12; k++)
    {
      Plane plane = k % 3 == 2 ? new Plane(0.4 + r.NextDouble(), 0.4 + r.NextDouble()) : new Plane(-r.NextDouble(), r.NextDouble(), -r.NextDouble(), r.NextDouble());
      var axis = new Vector3d(r.NextDouble() - 0.5, r.NextDouble() - 0.5, r.NextDouble() - 0.5);
      Matrix4d toParent = Matrix4d.Scale(0.5 + r.NextDouble()) * Matrix4d.Rotate(axis, r.NextDouble() * 6.0) *
                          Matrix4d.CreateTranslation(4.0 * r.NextDouble() - 2.0, 4.0 * r.NextDouble() - 2.0, 4.0 * r.NextDouble() - 2.0);
      root.InsertChild(plane, toParent);
      double x1 = plane.Triangle ? 1.0 / plane.XMax : plane.XMax, y1 = plane.Triangle ? 1.0 / plane.YMax : plane.YMax;
      corners.Add(Vector3d.TransformPosition(new Vector3d(plane.XMin, plane.YMin, 0.0), toParent));
      corners.Add(Vector3d.TransformPosition(new Vector3d(x1, plane.YMin, 0.0), toParent));
      corners.Add(Vector3d.TransformPosition(new Vector3d(plane.XMin, y1, 0.0), toParent));
    }
    root.InsertChild(new Sphere(), Matrix4d.Scale(0.7));
    PreparedScene ps = PreparedScene.Prepare(root);
    Assert.Equal(12, ps.UnboundedCount);
    var lists = new SceneLists(root);

    int hits = 0, blocked = 0;
    for (int n = 0; n < 20000; n++)
    {
      var p0 = new Vector3d(8.0 * r.NextDouble() - 4.0, 8.0 * r.NextDouble() - 4.0, 8.0 * r.NextDouble() - 4.0);
      Vector3d p1 = n % 4 == 0
        ? corners[r.Next(corners.Count)] - p0
        : new Vector3d(r.NextDouble() - 0.5, r.NextDouble() - 0.5, r.NextDouble() - 0.5);
      if (n % 7 == 0)
        p1.Y = 0.0;   // a zero component: the line test steps aside
      (bool hit, bool blocks) = AssertSameAnswers(lists, ps, p0, p1, compareEnter: false);
      hits += hit ? 1 : 0;
      blocked += blocks ? 1 : 0;
    }
    Assert.True(hits > 2000 && blocked > 1000, $"{hits} hits, {blocked} blocked");
  }

  /// <summary>The prepared scene's first hit (solid, T, and the side when asked) and shadow answer equal GrCis's lists' for one ray; whether it hit and was blocked.</summary>
  internal static (bool Hit, bool Blocked) AssertSameAnswers(SceneLists lists, PreparedScene ps, Vector3d p0, Vector3d p1, bool compareEnter)
  {
    Intersection? a = lists.FirstHit(p0, p1);
    Intersection? b = ps.FirstHit(p0, p1);
    Assert.Equal(a == null, b == null);
    if (a != null && b != null)
    {
      Assert.Same(a.Solid, b.Solid);
      Assert.Equal(a.T, b.T);
      if (compareEnter)
        Assert.Equal(a.Enter, b.Enter);
    }
    return (a != null && b != null, AssertSameShadow(lists, ps, p0, p1));
  }

  /// <summary>The prepared scene's shadow answer for <paramref name="p0"/> towards <c>p0 + dir</c> equals GrCis's lists'; whether it is blocked.</summary>
  internal static bool AssertSameShadow(SceneLists lists, PreparedScene ps, Vector3d p0, Vector3d dir)
  {
    bool expected = lists.AnyHit(p0, dir);
    Assert.Equal(expected, ps.AnyHit(p0, dir));
    return expected;
  }

  [Fact]
  public void Four_wide_bvh_over_hundreds_of_solids_answers_as_the_lists_do()
  {
    // 300 spheres and cubes, scaled and placed at random so that many overlap and many boxes nest, touch or
    // coincide (twins); rays from outside, from inside members and from hit points, some axis-parallel.
    var r = new Random(26);
    var root = new CSGInnerNode(SetOperation.Union);
    var group = new CSGInnerNode(SetOperation.Union);
    for (int k = 0; k < 300; k++)
    {
      ISolid solid = k % 3 == 0 ? new Cube() : new Sphere();
      Matrix4d toParent = Matrix4d.Scale(0.05 + 0.4 * r.NextDouble()) *
                          Matrix4d.CreateTranslation(6.0 * r.NextDouble() - 3.0, 6.0 * r.NextDouble() - 3.0, 6.0 * r.NextDouble() - 3.0);
      (k % 2 == 0 ? root : group).InsertChild(solid, toParent);
      if (k % 50 == 0)
        root.InsertChild(k % 3 == 0 ? new Cube() : new Sphere(), toParent);   // a twin: equal T, the first one wins
    }
    root.InsertChild(group, Matrix4d.CreateTranslation(0.1, 0.0, 0.0));
    PreparedScene ps = PreparedScene.Prepare(root);
    Assert.True(ps.BoundedCount > 300);
    var lists = new SceneLists(root);

    int hits = 0, blocked = 0;
    for (int n = 0; n < 20000; n++)
    {
      var p0 = new Vector3d(10.0 * r.NextDouble() - 5.0, 10.0 * r.NextDouble() - 5.0, 10.0 * r.NextDouble() - 5.0);
      var p1 = new Vector3d(r.NextDouble() - 0.5, r.NextDouble() - 0.5, r.NextDouble() - 0.5);
      if (n % 5 == 0)
        p1 = -p0 + new Vector3d(0.3 * r.NextDouble(), 0.3 * r.NextDouble(), 0.3 * r.NextDouble());   // through the crowd
      if (n % 7 == 0)
        p1 = new Vector3d(n % 2 == 0 ? 0.0 : -0.0, p1.Y, n % 3 == 0 ? 0.0 : p1.Z);
      if (n % 4 == 1 && lists.FirstHit(p0, p1) is Intersection start)
      {
        // From a surface point on, as secondary and shadow rays start.
        p0 = start.CoordWorld;
        p1 = new Vector3d(r.NextDouble() - 0.5, r.NextDouble() - 0.5, r.NextDouble() - 0.5);
      }
      (bool hit, bool blocks) = AssertSameAnswers(lists, ps, p0, p1, compareEnter: true);
      hits += hit ? 1 : 0;
      blocked += blocks ? 1 : 0;
    }
    Assert.True(hits > 5000 && blocked > 2000, $"{hits} hits, {blocked} blocked");
  }

  [Fact]
  public void Fast_path_rarely_falls_back_on_a_flake()
  {
    IRayScene scene = TestScenes.Flake9(2);
    var f = new RayTracing(scene);
    var renderer = new SimpleImageSynthesizer { Width = 64, Height = 48 };
    global::Rendering.Execution.TileRenderer.Render(scene, f, renderer, new global::Rendering.Execution.RenderOptions { Threads = 1 });
    long fallbacks = f.LastPrepared!.FallbackCount;
    // Opaque spheres, camera outside: only numerically-inside rays at sphere contacts may fall back.
    Assert.True(fallbacks < 64 * 48 / 100, $"{fallbacks} fallbacks");
  }
}
