using System;
using System.Collections.Generic;
using GrCis.Testing;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Rendering.Imaging;
using Xunit.Abstractions;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>
/// The allocation-free CSG kernel lists the same records as <see cref="CSGInnerNode.Intersect"/> (bits of T,
/// local coordinates, Enter as the merges left it, Front, solid data), picks the same first hit, and is used
/// for the classic CSG scenes; subtrees it cannot evaluate stay on the list path.
/// </summary>
public class CsgKernelTests
{
  readonly ITestOutputHelper output;

  public CsgKernelTests(ITestOutputHelper output) => this.output = output;

  // ---------------------------------------------------------------- random trees

  static Matrix4d RandomTransform(Random rnd)
  {
    switch (rnd.Next(4))
    {
      case 0:
        return Matrix4d.Identity;
      case 1:
        return Matrix4d.CreateTranslation(rnd.NextDouble() - 0.5, rnd.NextDouble() - 0.5, rnd.NextDouble() - 0.5);
      default:
        var axis = new Vector3d(rnd.NextDouble() - 0.5, rnd.NextDouble() - 0.5, rnd.NextDouble() - 0.5 + 1e-3);
        return Matrix4d.Scale(0.5 + rnd.NextDouble(), 0.5 + rnd.NextDouble(), 0.5 + rnd.NextDouble()) *
               Matrix4d.Rotate(axis, rnd.NextDouble() * 6.0) *
               Matrix4d.CreateTranslation(rnd.NextDouble() - 0.5, rnd.NextDouble() - 0.5, rnd.NextDouble() - 0.5);
    }
  }

  /// <summary>Every kind of solid with an <see cref="IRecordSolid.IntersectAll"/>, open and closed, one- and two-sided.</summary>
  static ISceneNode RandomSolid(Random rnd)
  {
    switch (rnd.Next(11))
    {
      case 0:
        return new Sphere();
      case 1:
        return new Cube();
      case 2:
        return new Cylinder(-0.5 - rnd.NextDouble(), 0.5 + rnd.NextDouble());
      case 3:
        return new Cylinder();
      case 4:
        return new Plane();
      case 5:
        return rnd.Next(2) == 0 ? new Plane(-1.0, 1.0, -0.5, 0.8) : new Plane(1.5, 1.2);
      case 6:
        return new SphereFront(rnd.Next(2) == 0);
      case 7:
        return new CylinderFront(-1.0, 1.0, rnd.Next(2) == 0);
      case 8:
        return new Torus(0.8, 0.3) { SelfHits = rnd.Next(2) == 0 };
      case 9:
        return new Torus(0.4, 0.6);   // spindle
      default:
        return new Torus(1.0, 0.2);
    }
  }

  static ISceneNode RandomTree(Random rnd, int depth, SetOperation? rootOp = null)
  {
    if (depth == 0 || (rootOp == null && rnd.Next(3) == 0))
      return RandomSolid(rnd);
    var node = new CSGInnerNode(rootOp ?? (SetOperation)rnd.Next(4));
    int children = 1 + rnd.Next(3);
    for (int i = 0; i < children; i++)
    {
      ISceneNode child = RandomTree(rnd, depth - 1);
      Matrix4d toParent = RandomTransform(rnd).Inverted();
      node.InsertChild(child, toParent);
      // Now and then a coincident twin: equal T in both operands (the merge's tie rule).
      if (rnd.Next(5) == 0 && Twin(child) is ISceneNode twin)
        node.InsertChild(twin, toParent);
    }
    return node;
  }

  static ISceneNode? Twin(ISceneNode node) => node switch
  {
    SphereFront f => new SphereFront(f.shell),
    Sphere => new Sphere(),
    Cube => new Cube(),
    CylinderFront => null,
    Cylinder c => new Cylinder(c.ZMin, c.ZMax),
    Torus t => new Torus(t.bigRadius, t.smallRadius) { SelfHits = t.SelfHits },
    _ => null,
  };

  static Vector3d RandomRayStart(Random rnd) =>
    new(rnd.NextDouble() * 4.0 - 2.0, rnd.NextDouble() * 4.0 - 2.0, rnd.NextDouble() * 4.0 - 2.0);

  static Vector3d RandomDirection(Random rnd)
  {
    var d = new Vector3d(rnd.NextDouble() * 2.0 - 1.0, rnd.NextDouble() * 2.0 - 1.0, rnd.NextDouble() * 2.0 - 1.0);
    // Lengths from 1e-3 to 1e2: the epsilon test uses the world |p1|².
    return d * Math.Pow(10.0, rnd.NextDouble() * 5.0 - 3.0);
  }

  [Theory]
  [InlineData(SetOperation.Intersection)]
  [InlineData(SetOperation.Difference)]
  [InlineData(SetOperation.Xor)]
  [InlineData(SetOperation.Union)]
  public void Random_trees_list_the_same_records_as_the_list_path(SetOperation op)
  {
    var rnd = new Random(1000 + (int)op);
    int trees = 0, records = 0, insideStarts = 0, hits = 0;
    for (int tree = 0; tree < 150; tree++)
    {
      var root = (CSGInnerNode)RandomTree(rnd, 3, op);
      CsgKernel? kernel = CsgKernel.TryCompile(root);
      if (kernel == null)
      {
        // Only a tree over more than 64 records may be refused.
        Assert.True(MaxRecords(root) > CsgKernel.MaxTotalRecords);
        continue;
      }
      trees++;
      var got = new SolidRecord[kernel.MaxRecords];
      var leaves = new int[kernel.MaxRecords];
      for (int ray = 0; ray < 300; ray++)
      {
        Vector3d p0 = RandomRayStart(rnd), p1 = RandomDirection(rnd);
        LinkedList<Intersection>? list = root.Intersect(p0, p1);
        int n = kernel.IntersectAll(p0, p1, got, leaves);
        Assert.Equal(list?.Count ?? 0, n);
        if (n == 0)
          continue;
        records += n;
        if (!list!.First!.Value.Enter)
          insideStarts++;
        int k = 0;
        foreach (Intersection expected in list)
        {
          AssertSameRecord(expected, kernel.Leaves[leaves[k]].RecordSolid!, got[k]);
          k++;
        }

        // The first accepted record and the inside state before it, as the union rule reads them.
        double len2 = (p1 * (0.5 + rnd.NextDouble())).LengthSquared;
        Intersection? first = null;
        bool state = !list.First.Value.Enter;
        foreach (Intersection i in list)
        {
          if (i.T > 0.0 && i.T * i.T * len2 > Intersection.RAY_EPSILON2)
          {
            first = i;
            break;
          }
          state = i.Enter;
        }
        int status = kernel.IntersectFirst(p0, p1, len2, out SolidRecord h, out int leaf, out bool inside);
        Assert.Equal(first != null ? 1 : 0, status);
        Assert.Equal(state, inside);
        if (first != null)
        {
          hits++;
          AssertSameRecord(first, kernel.Leaves[leaf].RecordSolid!, h);
        }
      }
    }
    output.WriteLine($"{op}: {trees} trees, {records} records, {insideStarts} lists starting inside, {hits} first hits");
    Assert.True(trees > 100, $"only {trees} trees compiled");
    Assert.True(records > 2000, $"only {records} records: the rays should hit the trees often");
    Assert.True(insideStarts > 50, $"only {insideStarts} lists start inside");
  }

  static int MaxRecords(ISceneNode node)
  {
    if (node is IRecordSolid f)
      return f.MaxRecords;
    int sum = 0;
    foreach (ISceneNode c in node.Children)
      sum += MaxRecords(c);
    return sum;
  }

  static void AssertSameRecord(Intersection expected, IRecordSolid solid, in SolidRecord hit)
  {
    Assert.Same(expected.Solid, solid);
    var actual = new Intersection(solid);
    solid.InitIntersection(hit, actual);
    Assert.Equal(BitConverter.DoubleToInt64Bits(expected.T), BitConverter.DoubleToInt64Bits(actual.T));
    Assert.Equal(expected.Enter, actual.Enter);
    Assert.Equal(expected.Front, actual.Front);
    AssertBits(expected.CoordLocal, actual.CoordLocal);
    AssertBits(expected.NormalLocal, actual.NormalLocal);
    Assert.Equal(expected.SolidData, actual.SolidData);
  }

  static void AssertBits(Vector3d a, Vector3d b)
  {
    Assert.Equal(BitConverter.DoubleToInt64Bits(a.X), BitConverter.DoubleToInt64Bits(b.X));
    Assert.Equal(BitConverter.DoubleToInt64Bits(a.Y), BitConverter.DoubleToInt64Bits(b.Y));
    Assert.Equal(BitConverter.DoubleToInt64Bits(a.Z), BitConverter.DoubleToInt64Bits(b.Z));
  }

  [Fact]
  public void Every_solid_lists_the_same_records_through_IntersectAll()
  {
    var rnd = new Random(5);
    var buffer = new SolidRecord[4];
    int records = 0;
    for (int s = 0; s < 200; s++)
    {
      var solid = (IRecordSolid)RandomSolid(rnd);
      Assert.True(solid.MaxRecords > 0);
      for (int ray = 0; ray < 100; ray++)
      {
        Vector3d p0 = RandomRayStart(rnd), p1 = RandomDirection(rnd);
        LinkedList<Intersection>? list = solid.Intersect(p0, p1);
        int n = solid.IntersectAll(p0, p1, buffer);
        Assert.Equal(list?.Count ?? 0, n);
        Assert.True(n <= solid.MaxRecords);
        int k = 0;
        if (list != null)
          foreach (Intersection i in list)
            AssertSameRecord(i, solid, buffer[k++]);
        records += n;
      }
    }
    Assert.True(records > 5000, $"only {records} records");
  }

  // ---------------------------------------------------------------- what the prepared scene hands to kernels

  [Theory]
  [InlineData("Hedgehog in the cage")]
  [InlineData("Flags")]
  [InlineData("Circus")]
  [InlineData("Toroids")]
  public void Classic_csg_scenes_use_kernels_and_no_lists(string name)
  {
    PreparedScene p = PreparedScene.Prepare(global::Rendering.Scenes.Create(name).Intersectable);
    output.WriteLine($"{name}: {p.MemberCount} members, {p.CsgMemberCount} CSG kernels, {p.ListMemberCount} through lists");
    Assert.True(p.CsgMemberCount > 0);
    Assert.Equal(0, p.ListMemberCount);
  }

  static CSGInnerNode Difference(ISceneNode a, ISceneNode b)
  {
    var d = new CSGInnerNode(SetOperation.Difference);
    d.InsertChild(a, Matrix4d.Identity);
    d.InsertChild(b, Matrix4d.Scale(0.6) * Matrix4d.CreateTranslation(0.5, 0.0, 0.0));
    return d;
  }

  [Fact]
  public void Mesh_script_bezier_animated_bounded_and_oversized_subtrees_stay_on_the_list_path()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.InsertChild(Difference(new Sphere(), new Cube()), Matrix4d.Identity);                                    // kernel
    root.InsertChild(Difference(new Sphere(), new TriangleMesh(ProceduralMesh.Torus(8, 4))), Matrix4d.Identity);  // mesh
    root.InsertChild(Difference(new ScriptSphere(), new Sphere()), Matrix4d.Identity);                           // script solid
    var net = new double[48];
    for (int i = 0; i < 16; i++)
    {
      net[3 * i] = i % 4;
      net[3 * i + 1] = i / 4;
    }
    root.InsertChild(Difference(new Sphere(), new BezierSurface(1, 1, net)), Matrix4d.Identity);                 // Bézier patch
    var animated = new AnimatedCSGInnerNode(SetOperation.Intersection);
    animated.InsertChild(new Sphere(), Matrix4d.Identity);
    animated.InsertChild(new Cube(), Matrix4d.Identity);
    root.InsertChild(animated, Matrix4d.Identity);                                                                // animated
    var big = new CSGInnerNode(SetOperation.Xor);
    for (int i = 0; i < 17; i++)
      big.InsertChild(new Torus(1.0, 0.2), Matrix4d.CreateTranslation(0.1 * i, 0.0, 0.0));                      // 68 records
    root.InsertChild(big, Matrix4d.Identity);
    var bounded = Difference(new Sphere(), new Cube());
    bounded.BoundingVolume = new NeverMissVolume();
    root.InsertChild(bounded, Matrix4d.Identity);                                                                 // bounding volume

    PreparedScene p = PreparedScene.Prepare(root);
    Assert.Equal(7, p.MemberCount);
    Assert.Equal(1, p.CsgMemberCount);
    Assert.Equal(6, p.ListMemberCount);
  }

  sealed class NeverMissVolume : IBoundingVolume
  {
    public double Intersect(Vector3d p0, Vector3d p1) => 0.0;
  }

  [Fact]
  public void Random_csg_scene_renders_identically_on_both_paths()
  {
    // Random trees of real solids as union members (in the BVH or, when open, tested always), a CSG root
    // of its own, glass and mirrors so that rays start inside, NO_SHADOW leaves.
    static IRayScene Build()
    {
      var rnd = new Random(42);
      var root = new CSGInnerNode(SetOperation.Union);
      root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
      root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.6, 0.6, 0.6 }, 0.1, 0.5, 0.4, 32) { n = 1.4, Kt = 0.5 });
      int placed = 0;
      while (placed < 9)
      {
        ISceneNode tree = RandomTree(rnd, 2, (SetOperation)rnd.Next(4));
        if (MaxRecords(tree) > CsgKernel.MaxTotalRecords)
          continue;
        tree.SetAttribute(PropertyName.COLOR, new[] { rnd.NextDouble(), rnd.NextDouble(), rnd.NextDouble() });
        foreach (ISceneNode c in tree.Children)
          if (rnd.Next(4) == 0)
            c.SetAttribute(PropertyName.NO_SHADOW, true);
        root.InsertChild(tree, Matrix4d.Scale(0.9) * Matrix4d.CreateTranslation(2.2 * (placed % 3) - 2.2, 2.2 * (placed / 3) - 2.2, 0.0));
        placed++;
      }
      return new DefaultRayScene
      {
        Intersectable = root,
        BackgroundColor = new[] { 0.0, 0.05, 0.07 },
        Camera = new StaticCamera(new Vector3d(0.3, 0.2, -9.0), new Vector3d(0, 0, 1), 60.0),
        Sources = new LinkedList<ILightSource>(new ILightSource[]
          { new AmbientLightSource(0.6), new PointLightSource(new Vector3d(-5, 4, -6), 1.0) }),
      };
    }

    PreparedScene p = PreparedScene.Prepare(Build().Intersectable);
    Assert.True(p.CsgMemberCount >= 5, $"{p.CsgMemberCount} CSG kernels");
    FloatImage slow = RenderHelper.Render(Build(), AccelMode.None, 96, 72);
    FloatImage fast = RenderHelper.Render(Build(), AccelMode.Bvh, 96, 72, threads: 2);
    int differing = 0;
    for (int k = 0; k < slow.Data.Length; k++)
      if (slow.Data[k] != fast.Data[k] && !(float.IsNaN(slow.Data[k]) && float.IsNaN(fast.Data[k])))
        differing++;
    output.WriteLine($"random CSG scene: {p.CsgMemberCount} kernels, {differing} differing channels");
    Assert.Equal(0, differing);
  }

  [Fact]
  public void A_csg_root_is_answered_by_its_kernel()
  {
    // The scene's intersectable itself is a difference: one member, no union merge.
    var diff = Difference(new Sphere(), new Torus(0.8, 0.3));
    PreparedScene p = PreparedScene.Prepare(diff);
    Assert.Equal(1, p.CsgMemberCount);
    var rnd = new Random(3);
    for (int ray = 0; ray < 2000; ray++)
    {
      Vector3d p0 = RandomRayStart(rnd), p1 = RandomDirection(rnd);
      Intersection? expected = Intersection.FirstIntersection(diff.Intersect(p0, p1), ref p1);
      Intersection? actual = p.FirstHit(p0, p1);
      Assert.Equal(expected == null, actual == null);
      if (expected == null)
        continue;
      Assert.Same(expected.Solid, actual!.Solid);
      Assert.Equal(expected.T, actual.T);
      Assert.Equal(expected.Enter, actual.Enter);
      Assert.Equal(expected.CoordLocal, actual.CoordLocal);
      Vector3d d = p1 * 0.5;
      Intersection? blocker = Intersection.FirstRealIntersection(diff.Intersect(p0, d), ref d);
      Assert.Equal(blocker != null && !blocker.Far(1.0, ref d), p.Occluded(p0, d));
    }
  }
}
