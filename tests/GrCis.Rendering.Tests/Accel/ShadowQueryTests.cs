using System;
using System.Collections.Generic;
using GrCis.Testing;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>
/// The shadow query that stops at the first blocker and the world-space cull of bounded rectangles
/// (<see cref="RectangleCull"/>): on random rays of several scenes (walls, CSG, meshes, NO_SHADOW solids, rays
/// from surface points and from inside solids), the prepared scene answers exactly as GrCis's lists do.
/// </summary>
public class ShadowQueryTests
{
  /// <summary>The path tracer's Cornell box (scripts/CornellBox.cs): nine rectangles under a mirroring root, two spheres.</summary>
  internal static CSGInnerNode CornellBox()
  {
    var top = new CSGInnerNode(SetOperation.Union);
    top.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    top.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.73, 0.73, 0.73 }, 0.0, 1.0, 0.0, 1));
    var root = new CSGInnerNode(SetOperation.Union);
    top.InsertChild(root, Matrix4d.Scale(-1.0, 1.0, 1.0));
    void Wall(double x0, double x1, double y0, double y1, Matrix4d place) => root.InsertChild(new Plane(x0, x1, y0, y1), place);
    Wall(-1, 1, -1, 1, Matrix4d.RotateX(-MathHelper.PiOver2));
    Wall(-1, 1, 0, 2, Matrix4d.CreateTranslation(0, 0, -1));
    Wall(-1, 1, 0, 2, Matrix4d.RotateY(MathHelper.PiOver2) * Matrix4d.CreateTranslation(-1, 0, 0));
    Wall(-1, 1, 0, 2, Matrix4d.RotateY(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(1, 0, 0));
    Matrix4d ceiling = Matrix4d.RotateX(MathHelper.PiOver2) * Matrix4d.CreateTranslation(0, 2, 0);
    Wall(-1, -0.25, -1, 1, ceiling);
    Wall(0.25, 1, -1, 1, ceiling);
    Wall(-0.25, 0.25, -1, -0.2, ceiling);
    Wall(-0.25, 0.25, 0.2, 1, ceiling);
    Wall(-0.25, 0.25, -0.2, 0.2, ceiling);
    root.InsertChild(new Sphere(), Matrix4d.Scale(0.4) * Matrix4d.CreateTranslation(-0.45, 0.4, -0.35));
    root.InsertChild(new Sphere(), Matrix4d.Scale(0.4) * Matrix4d.CreateTranslation(0.45, 0.4, 0.35));
    return top;
  }

  [Fact]
  public void Cornell_box_walls_are_culled_in_world_space_and_shadow_rays_stop_at_the_first_blocker()
  {
    PreparedScene ps = PreparedScene.Prepare(CornellBox());
    Assert.Equal(9, ps.CulledRectangleCount);
    Assert.Equal(2, ps.CulledBallCount);
    Assert.Equal(9, ps.UnboundedCount);
    Assert.True(ps.StopsAtFirstBlocker);
  }

  [Fact]
  public void Cornell_box_answers_as_the_lists_on_path_like_rays()
  {
    CSGInnerNode box = CornellBox();
    var (hits, blocked) = CompareOnRandomRays(box, new Random(3), 30000, new Vector3d(-1, 0, -1), new Vector3d(1, 2, 1),
                                              new Vector3d(0, 1.999999, 0), 0.25);
    Assert.True(hits > 20000 && blocked > 2000, $"{hits} hits, {blocked} blocked");
  }

  public static TheoryData<string> SceneNames()
  {
    var data = new TheoryData<string>();
    foreach ((string name, _) in TestScenes.All)
      data.Add(name);
    foreach (string name in new[] { "Five balls", "Cubes", "Cylinders", "Circus", "Bezier", "Hedgehog in the cage", "Test scene" })
      data.Add("classic:" + name);
    return data;
  }

  [Theory]
  [MemberData(nameof(SceneNames))]
  public void First_hits_and_shadow_answers_equal_the_lists_on_random_rays(string name)
  {
    IIntersectable root = name.StartsWith("classic:", StringComparison.Ordinal)
      ? global::Rendering.Scenes.Create(name.Substring(8)).Intersectable!
      : TestScenes.All[IndexOf(name)].Build().Intersectable!;
    var (hits, _) = CompareOnRandomRays(root, new Random(name.Length * 31 + 7), 4000, new Vector3d(-6), new Vector3d(6), new Vector3d(-10, 12, -8), 3.0);
    Assert.True(hits > 50, $"{hits} hits");
  }

  [Fact]
  public void A_no_shadow_solid_keeps_the_closest_record_rule_and_the_answers()
  {
    // A NO_SHADOW sphere around a real one: the lists see only the ghost's records, so nothing blocks; any-hit is off.
    var root = new CSGInnerNode(SetOperation.Union);
    var ghost = new Sphere();
    ghost.SetAttribute(PropertyName.NO_SHADOW, true);
    root.InsertChild(ghost, Matrix4d.Scale(2.0));
    root.InsertChild(new Sphere(), Matrix4d.Scale(0.5));
    root.InsertChild(new Plane(-3, 3, -3, 3), Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0, -2.5, 0));
    PreparedScene ps = PreparedScene.Prepare(root);
    Assert.False(ps.StopsAtFirstBlocker);
    Assert.False(ps.Occluded(new Vector3d(0, 0, -5), new Vector3d(0, 0, 10)));
    CompareOnRandomRays(root, new Random(11), 5000, new Vector3d(-3), new Vector3d(3), new Vector3d(0, 5, 0), 1.0);
  }

  [Fact]
  public void Rays_from_inside_a_solid_past_a_smaller_one_are_not_blocked_as_the_lists_say()
  {
    // Inside the big sphere the union hides the small one: no shadow although the small sphere lies between.
    var root = new CSGInnerNode(SetOperation.Union);
    root.InsertChild(new Sphere(), Matrix4d.Scale(10.0));
    root.InsertChild(new Sphere(), Matrix4d.Identity);
    PreparedScene ps = PreparedScene.Prepare(root);
    Assert.True(ps.StopsAtFirstBlocker);
    var lists = new SceneLists(root);
    var p0 = new Vector3d(0, 0, -5);
    var dir = new Vector3d(0, 0, 10);
    Assert.False(lists.AnyHit(p0, dir));
    Assert.False(ps.AnyHit(p0, dir));
    // Outside both, the small one blocks.
    Assert.True(ps.AnyHit(new Vector3d(0, 0, -50), new Vector3d(0, 0, 60)));
    Assert.Equal(lists.AnyHit(new Vector3d(0, 0, -50), new Vector3d(0, 0, 60)), ps.AnyHit(new Vector3d(0, 0, -50), new Vector3d(0, 0, 60)));
  }

  [Fact]
  public void Rectangles_under_long_chains_and_far_from_the_origin_answer_as_the_lists()
  {
    // Rectangles behind three or four random transforms (rotations, uneven scales, large translations that cancel),
    // rays from their surfaces (t = 0 records), along their planes and at their edges.
    var r = new Random(42);
    var root = new CSGInnerNode(SetOperation.Union);
    var edges = new List<Vector3d>();
    var inside = new List<Vector3d>();
    for (int k = 0; k < 14; k++)
    {
      var plane = new Plane(-r.NextDouble(), r.NextDouble(), -r.NextDouble(), r.NextDouble());
      var inner = new CSGInnerNode(SetOperation.Union);
      var far = new Vector3d(1.0e5 * (r.NextDouble() - 0.5), 1.0e5 * (r.NextDouble() - 0.5), 0.0);
      Matrix4d a = Matrix4d.Scale(0.3 + r.NextDouble(), 0.3 + 2.0 * r.NextDouble(), 1.0 + r.NextDouble()) *
                   Matrix4d.Rotate(new Vector3d(r.NextDouble(), r.NextDouble() - 0.5, r.NextDouble()), 6.0 * r.NextDouble()) *
                   Matrix4d.CreateTranslation(far);
      Matrix4d b = Matrix4d.CreateTranslation(-far + new Vector3d(3.0 * r.NextDouble() - 1.5, 3.0 * r.NextDouble() - 1.5, 3.0 * r.NextDouble() - 1.5));
      Matrix4d place = k % 2 == 0 ? b : b * Matrix4d.RotateZ(r.NextDouble());
      inner.InsertChild(plane, a);
      root.InsertChild(inner, place);
      Matrix4d toWorld = a * place;
      edges.Add(Vector3d.TransformPosition(new Vector3d(plane.XMax, 0.5 * (plane.YMin + plane.YMax), 0.0), toWorld));
      inside.Add(Vector3d.TransformPosition(new Vector3d(0.5 * plane.XMin, 0.5 * plane.YMax, 0.0), toWorld));
    }
    root.InsertChild(new Cube(), Matrix4d.Scale(0.6));
    PreparedScene ps = PreparedScene.Prepare(root);
    Assert.Equal(14, ps.CulledRectangleCount);
    var lists = new SceneLists(root);
    for (int n = 0; n < 20000; n++)
    {
      var p0 = new Vector3d(6.0 * r.NextDouble() - 3.0, 6.0 * r.NextDouble() - 3.0, 6.0 * r.NextDouble() - 3.0);
      Vector3d p1 = n % 3 == 0 ? edges[r.Next(edges.Count)] - p0 : RandomDirection(r);
      if (n % 2 == 1 && lists.FirstHit(p0, p1) is Intersection start)
      {
        p0 = start.CoordWorld;
        p1 = n % 4 == 1 ? RandomDirection(r) * 5.0 : edges[r.Next(edges.Count)] - p0;
      }
      if (n % 5 == 4)
      {
        // Meeting a rectangle (from either side) at 0.3 to 3 times the smallest accepted t: records the union
        // skips, the inside state they leave, and entries just beyond the epsilon.
        p1 = RandomDirection(r) * (0.2 + 5.0 * r.NextDouble());
        p0 = inside[r.Next(inside.Count)] - p1 * ((0.3 + 2.7 * r.NextDouble()) * Intersection.RAY_EPSILON / p1.Length);
      }
      PreparedSceneTests.AssertSameAnswers(lists, ps, p0, p1, compareEnter: true);
    }
  }

  [Theory]
  [InlineData(1)]
  [InlineData(6)]
  [InlineData(8)]
  public void A_few_balls_tested_side_by_side_answer_as_the_lists(int count)
  {
    // Spheres under random similarities (some overlapping, one far from the origin) and a floor rectangle; rays from
    // outside, from inside the spheres, from their surfaces, and grazing them.
    var r = new Random(count);
    var root = new CSGInnerNode(SetOperation.Union);
    var centres = new List<(Vector3d C, double R)>();
    for (int k = 0; k < count; k++)
    {
      double radius = 0.2 + r.NextDouble();
      var c = k == count - 1 ? new Vector3d(1000.0, 1000.0, 1000.0) * (count > 1 ? 1.0 : 0.0) + new Vector3d(r.NextDouble(), 0.5, 0.0)
                             : new Vector3d(4.0 * r.NextDouble() - 2.0, 4.0 * r.NextDouble() - 2.0, 4.0 * r.NextDouble() - 2.0);
      root.InsertChild(new Sphere(), Matrix4d.Scale(radius) * Matrix4d.Rotate(new Vector3d(r.NextDouble(), 1.0, r.NextDouble()), 6.0 * r.NextDouble()) *
                                     Matrix4d.CreateTranslation(c));
      centres.Add((c, radius));
    }
    root.InsertChild(new Plane(-3, 3, -3, 3), Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0, -2.5, 0));
    PreparedScene ps = PreparedScene.Prepare(root);
    Assert.Equal(count, ps.CulledBallCount);
    var lists = new SceneLists(root);
    int hits = 0;
    for (int n = 0; n < 20000; n++)
    {
      var (c, radius) = centres[r.Next(centres.Count)];
      Vector3d p0 = n % 3 == 0 ? c + RandomDirection(r) * radius : new Vector3d(8.0 * r.NextDouble() - 4.0, 8.0 * r.NextDouble() - 4.0, 8.0 * r.NextDouble() - 4.0);
      Vector3d p1 = n % 4 == 0 ? c - p0 + RandomDirection(r) * (2.0 * radius) : RandomDirection(r) * (0.1 + 3.0 * r.NextDouble());
      if (n % 5 == 1 && lists.FirstHit(p0, p1) is Intersection start)
      {
        p0 = start.CoordWorld;
        p1 = n % 2 == 0 ? RandomDirection(r) : c - p0;
      }
      hits += PreparedSceneTests.AssertSameAnswers(lists, ps, p0, p1, compareEnter: true).Hit ? 1 : 0;
    }
    Assert.True(hits > 2000, $"{hits} hits");
  }

  [Fact]
  public void Nine_balls_go_into_the_bvh()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    for (int k = 0; k < 9; k++)
      root.InsertChild(new Sphere(), Matrix4d.CreateTranslation(3.0 * k, 0.0, 0.0));
    PreparedScene ps = PreparedScene.Prepare(root);
    Assert.Equal(0, ps.CulledBallCount);
    Assert.Equal(9, ps.BoundedCount);
  }

  /// <summary>
  /// Camera-like rays from random points of [lo, hi], then path-like rays from their hits, and shadow rays from
  /// those hits to random points around <paramref name="light"/>, compared with the lists; counts hits and blocked rays.
  /// </summary>
  static (int Hits, int Blocked) CompareOnRandomRays(IIntersectable root, Random r, int count, Vector3d lo, Vector3d hi, Vector3d light, double spread)
  {
    PreparedScene ps = PreparedScene.Prepare(root);
    var lists = new SceneLists(root);
    int hits = 0, blocked = 0;
    for (int n = 0; n < count; n++)
    {
      var p0 = new Vector3d(lo.X + (hi.X - lo.X) * r.NextDouble(), lo.Y + (hi.Y - lo.Y) * r.NextDouble(), lo.Z + (hi.Z - lo.Z) * r.NextDouble());
      Vector3d p1 = RandomDirection(r);
      if (n % 9 == 0)
        p1.X = 0.0;   // a zero component
      for (int bounce = 0; bounce < 3; bounce++)
      {
        (bool hit, bool blocks) = PreparedSceneTests.AssertSameAnswers(lists, ps, p0, p1, compareEnter: true);
        hits += hit ? 1 : 0;
        blocked += blocks ? 1 : 0;
        Intersection? i = lists.FirstHit(p0, p1);
        if (i == null)
          break;
        // A shadow ray as the path tracer sends it (stopping short of the light), and one to a random point.
        Vector3d x = i.CoordWorld;
        Vector3d target = light + new Vector3d(spread * (r.NextDouble() - 0.5), 0.0, spread * (r.NextDouble() - 0.5));
        Vector3d toLight = target - x;
        double dist = toLight.Length;
        blocked += PreparedSceneTests.AssertSameShadow(lists, ps, x, toLight * (1.0 - 4.0 * Intersection.RAY_EPSILON / dist)) ? 1 : 0;
        blocked += PreparedSceneTests.AssertSameShadow(lists, ps, x, lo + (hi - lo) * r.NextDouble() - x) ? 1 : 0;
        p0 = x;
        p1 = RandomDirection(r);
      }
    }
    return (hits, blocked);
  }

  static Vector3d RandomDirection(Random r) => new(r.NextDouble() - 0.5, r.NextDouble() - 0.5, r.NextDouble() - 0.5);

  static int IndexOf(string name)
  {
    for (int k = 0; k < TestScenes.All.Count; k++)
      if (TestScenes.All[k].Name == name)
        return k;
    throw new ArgumentException(name);
  }
}
