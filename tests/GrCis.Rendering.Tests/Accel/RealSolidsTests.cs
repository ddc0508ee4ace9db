using Scene3D;
using System.Collections.Generic;
using GrCis.Testing;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Rendering.Imaging;
using Xunit.Abstractions;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>The library's own solids and meshes on the fast path: used, identical images, no garbage per ray.</summary>
public class RealSolidsTests
{
  readonly ITestOutputHelper output;

  public RealSolidsTests(ITestOutputHelper output) => this.output = output;

  [Theory]
  [InlineData("Five balls")]
  [InlineData("Hedgehog in the cage")]
  [InlineData("Flags")]
  [InlineData("Sphere on the plane")]
  [InlineData("Two spheres")]
  [InlineData("Sphere flake")]
  [InlineData("Cubes")]
  [InlineData("Cylinders")]
  [InlineData("Circus")]
  [InlineData("Toroids")]
  public void Classic_scene_solids_all_answer_through_the_allocation_free_kernels(string name)
  {
    PreparedScene p = PreparedScene.Prepare(global::Rendering.Scenes.Create(name).Intersectable);
    output.WriteLine($"{name}: {p.MemberCount} members, {p.BoundedCount} in the BVH, {p.UnboundedCount} always tested, {p.CsgMemberCount} CSG kernels, {p.ListMemberCount} through lists");
    Assert.True(p.MemberCount > 0);
    // Every solid has a kernel, and every non-union CSG subtree the CSG kernel: nothing goes through lists.
    Assert.Equal(CountNonUnion(global::Rendering.Scenes.Create(name).Intersectable), p.CsgMemberCount);
    Assert.Equal(0, p.ListMemberCount);
  }

  static int CountNonUnion(IIntersectable? node)
  {
    if (node is not ISceneNode sn)
      return 0;
    if (node.GetType() == typeof(CSGInnerNode) && ((CSGInnerNode)node).Operation != SetOperation.Union)
      return 1;
    int n = 0;
    foreach (ISceneNode c in sn.Children)
      n += CountNonUnion(c);
    return n;
  }

  sealed class BiggerSphere : Sphere
  {
    public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1) => base.Intersect(p0 * 0.5, p1 * 0.5);
  }

  sealed class TintedSphere : Sphere
  {
  }

  [Fact]
  public void A_subclass_that_overrides_Intersect_is_answered_through_its_list()
  {
    Assert.False(new BiggerSphere().RecordsMatchIntersect);
    Assert.True(new TintedSphere().RecordsMatchIntersect);
    Assert.True(new SphereFront().RecordsMatchIntersect);
    Assert.False(new TriangleMesh(ProceduralMesh.Torus(8, 4)) { ShellMode = true }.RecordsMatchIntersect);
  }

  [Fact]
  public void Real_sphere_flake9_renders_identically_on_both_paths()
  {
    var a = new DefaultRayScene();
    global::Rendering.Scenes.SphereFlake9(a, 2);
    var b = new DefaultRayScene();
    global::Rendering.Scenes.SphereFlake9(b, 2);
    Assert.Equal(91, PreparedScene.Prepare(a.Intersectable).BoundedCount);
    AssertIdentical("flake9 depth 2", RenderHelper.Render(a, AccelMode.None, 80, 60), RenderHelper.Render(b, AccelMode.Bvh, 80, 60, threads: 2));
  }

  static IRayScene Mesh(SceneBrep m, bool tilt)
  {
    var sc = new DefaultRayScene();
    global::Rendering.Scenes.MeshScene(sc, m, tilt);
    return sc;
  }

  /// <summary>An open, wavy sheet: rays see both sides, and many lists start "inside".</summary>
  static SceneBrep Sheet(int n)
  {
    var m = new SceneBrep();
    for (int i = 0; i <= n; i++)
      for (int j = 0; j <= n; j++)
      {
        double x = -1.0 + 2.0 * i / n, y = -1.0 + 2.0 * j / n;
        m.AddVertex(new Vector3((float)x, (float)y, (float)(0.3 * System.Math.Sin(3 * x) * System.Math.Cos(2 * y))));
      }
    for (int i = 0; i < n; i++)
      for (int j = 0; j < n; j++)
      {
        int a = i * (n + 1) + j;
        m.AddTriangle(a, a + n + 1, a + n + 2);
        m.AddTriangle(a, a + n + 2, a + 1);
      }
    return m;
  }

  [Theory]
  [InlineData("closed torus", true)]
  [InlineData("open sheet", false)]
  public void Mesh_scene_renders_identically_on_both_paths(string kind, bool closed)
  {
    SceneBrep Make() => closed ? ProceduralMesh.Torus(40, 20) : Sheet(16);
    FloatImage slow = RenderHelper.Render(Mesh(Make(), closed), AccelMode.None, 80, 60);
    FloatImage fast = RenderHelper.Render(Mesh(Make(), closed), AccelMode.Bvh, 80, 60, threads: 2);
    AssertIdentical(kind, slow, fast);
  }

  [Fact]
  public void Faithful_path_tests_every_triangle_without_building_the_mesh_bvh()
  {
    // GrCis had no search structures: --accel none must not build one, and must list the same hits.
    IRayScene slowScene = Mesh(ProceduralMesh.Torus(40, 20), tilt: true);
    RenderHelper.Render(slowScene, AccelMode.None, 40, 30);
    TriangleMesh slowMesh = FindMesh(slowScene.Intersectable!);
    Assert.False(slowMesh.HasBvh);

    IRayScene fastScene = Mesh(ProceduralMesh.Torus(40, 20), tilt: true);
    RenderHelper.Render(fastScene, AccelMode.Bvh, 40, 30);
    Assert.True(FindMesh(fastScene.Intersectable!).HasBvh);

    // Ray by ray, the brute-force list equals the BVH's list record for record (bits of T included).
    var mesh = new TriangleMesh(ProceduralMesh.Torus(40, 20));
    var rnd = new System.Random(7);
    int crossings = 0;
    for (int n = 0; n < 2000; n++)
    {
      var p0 = new Vector3d(rnd.NextDouble() * 6 - 3, rnd.NextDouble() * 6 - 3, rnd.NextDouble() * 6 - 3);
      var p1 = new Vector3d(rnd.NextDouble() * 2 - 1, rnd.NextDouble() * 2 - 1, rnd.NextDouble() * 2 - 1) - 0.1 * p0;
      var brute = ExhaustiveSearch.Intersect(mesh, p0, p1);
      var tree = mesh.Intersect(p0, p1);
      Assert.Equal(tree?.Count ?? 0, brute?.Count ?? 0);
      if (tree == null)
        continue;
      crossings += tree.Count;
      using var a = tree.GetEnumerator();
      using var b = brute!.GetEnumerator();
      while (a.MoveNext() && b.MoveNext())
      {
        Assert.Equal(a.Current.T, b.Current.T);
        Assert.Equal(a.Current.Enter, b.Current.Enter);
        Assert.Equal(a.Current.CoordLocal, b.Current.CoordLocal);
      }
    }
    Assert.True(crossings > 500, $"only {crossings} crossings: the rays should hit the torus often");
  }

  static TriangleMesh FindMesh(IIntersectable root) => Find(root) ?? throw new Xunit.Sdk.XunitException("no mesh in the scene");

  static TriangleMesh? Find(IIntersectable node)
  {
    if (node is TriangleMesh m)
      return m;
    if (node is ISceneNode sn)
      foreach (ISceneNode child in sn.Children)
        if (Find(child) is TriangleMesh found)
          return found;
    return null;
  }

  [Fact]
  public void Procedural_torus_has_the_asked_triangle_count_and_outward_faces()
  {
    SceneBrep m = ProceduralMesh.Torus(100, 50);
    Assert.Equal(10_000, m.Triangles);
    // A ray from outside along -x hits the outer wall first, from the front.
    var mesh = new TriangleMesh(m);
    Assert.True(mesh.IntersectFirst(new Vector3d(5, 0.01, 0.01), new Vector3d(-1, 0, 0), 1.0, out SolidRecord h, out bool inside));
    Assert.False(inside);
    Assert.True(h.Enter);
    Assert.Equal(5.0 - 1.4, h.T, 2);
  }

  void AssertIdentical(string name, FloatImage expected, FloatImage actual)
  {
    int differing = 0;
    double maxDiff = 0.0;
    for (int k = 0; k < expected.Data.Length; k++)
    {
      double d = System.Math.Abs(expected.Data[k] - actual.Data[k]);
      if (d != 0.0 || float.IsNaN(expected.Data[k]) != float.IsNaN(actual.Data[k]))
      {
        differing++;
        maxDiff = System.Math.Max(maxDiff, d);
      }
    }
    output.WriteLine($"{name}: {differing} differing channels, max difference {maxDiff}");
    Assert.True(differing == 0, $"{name}: {differing} channels differ (max {maxDiff}).");
  }
}
