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
