using System;
using System.Collections.Concurrent;
using System.Collections.Generic;
using System.Linq;
using MathSupport;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;
using Utilities;

namespace GrCis.Rendering.Tests.Compatibility;

/// <summary>
/// Members of GrCis's library that students' code calls or overrides, with GrCis's names and meanings.
/// </summary>
public class TeachingApiTests
{
  /// <summary>A student's camera: parameterless base constructor, fields set by hand, its own prepare().</summary>
  sealed class StudentCamera : StaticCamera
  {
    public int Prepared;

    public StudentCamera(Vector3d position, Vector3d target)
    {
      center = position;
      direction = (target - position).Normalized();
      hAngle = Arith.DegreeToRadian(60.0);
      Width = 64;      // the setters call prepare(), which this class overrides
      Height = 48;
    }

    protected override void prepare()
    {
      Prepared++;
      base.prepare();
    }
  }

  [Fact]
  public void A_camera_subclass_built_with_the_parameterless_constructor_overrides_prepare_and_shoots_rays()
  {
    var camera = new StudentCamera(new Vector3d(0, 0, -5), Vector3d.Zero);
    Assert.Equal(2, camera.Prepared);
    var reference = new StaticCamera(new Vector3d(0, 0, -5), new Vector3d(0, 0, 1), 60.0) { Width = 64, Height = 48 };
    Assert.True(camera.GetRay(32, 24, out Vector3d p0, out Vector3d p1));
    Assert.True(reference.GetRay(32, 24, out Vector3d q0, out Vector3d q1));
    Assert.Equal(q0, p0);
    Assert.True((p1 - q1).Length < 1e-6, $"{p1} vs {q1}");   // GrCis's float angle conversion vs ours
  }

  sealed class Clock : ITimeDependent
  {
    public double Start { get; set; }
    public double End { get; set; } = 1.0;
    public double Time { get; set; }
    public object Clone() => new Clock { Start = Start, End = End, Time = Time };
  }

  sealed class MovingNode : DefaultSceneNode, ITimeDependent
  {
    public double Start { get; set; }
    public double End { get; set; } = 1.0;
    public double Time { get; set; }

    // The GrCis way of writing a time-dependent node's clone.
    public object Clone()
    {
      var n = new MovingNode { Start = Start, End = End, Time = Time, ToParent = ToParent };
      ShareCloneAttributes(n);
      ShareCloneChildren(n);
      return n;
    }
  }

  [Fact]
  public void ShareClone_helpers_clone_time_dependent_parts_and_share_the_rest_without_reparenting_shared_children()
  {
    var node = new MovingNode();
    var staticChild = new Sphere();
    var movingChild = new MovingNode();
    node.InsertChild(staticChild, Matrix4d.CreateTranslation(1, 0, 0));
    node.InsertChild(movingChild, Matrix4d.Identity);
    double[] color = { 0.1, 0.2, 0.3 };
    var clock = new Clock();
    var material = new PhongMaterial(new double[] { 1, 1, 1 }, 0.1, 0.8, 0.1, 16);
    node.SetAttribute(PropertyName.COLOR, color);
    node.SetAttribute("clock", clock);
    node.SetAttribute(PropertyName.MATERIAL, material);
    node.SetAttribute(PropertyName.TEXTURE, new List<ITexture> { new CheckerTexture(1, 1, new double[] { 0, 0, 0 }) });

    var copy = (MovingNode)node.Clone();

    ISceneNode[] children = copy.Children.ToArray();
    Assert.Equal(2, children.Length);
    Assert.NotSame(movingChild, children[1]);
    Assert.IsType<MovingNode>(children[1]);
    Assert.IsType<Sphere>(children[0]);
    Assert.Same(copy, children[0].Parent);
    Assert.Same(node, staticChild.Parent);             // the original child was not re-parented
    Assert.Equal(staticChild.ToParent, children[0].ToParent);

    double[] copiedColor = Assert.IsType<double[]>(copy.GetLocalAttribute(PropertyName.COLOR));
    Assert.NotSame(color, copiedColor);                // arrays are ICloneable: copied
    Assert.Equal(color, copiedColor);
    Assert.NotSame(clock, copy.GetLocalAttribute("clock"));
    Assert.IsAssignableFrom<IEnumerable<ITexture>>(copy.GetLocalAttribute(PropertyName.TEXTURE));
    Assert.Single(copy.GetTextures()!);
  }

  [Fact]
  public void ShareCloneAttributes_of_a_node_without_attributes_leaves_none()
  {
    var a = new MovingNode();
    var b = new MovingNode();
    b.SetAttribute(PropertyName.COLOR, new double[] { 1, 0, 0 });
    a.ShareCloneAttributes(b);
    Assert.Null(b.GetLocalAttribute(PropertyName.COLOR));
  }

  [Fact]
  public void Util_and_Arith_helpers_behave_as_in_GrCis()
  {
    Assert.Equal(5, Util.Clamp(9, 1, 5));
    Assert.Equal(-1.5, Arith.Clamp(-1.5, -2.0, 2.0));
    Assert.Equal("b", Util.Clamp("z", "a", "b"));
    Assert.Equal(1.0, Util.Saturate(3.0));
    Assert.Equal(0.0f, Util.Saturate(-1.0f));
    Assert.Equal(3, Util.bits(0b1011));
    Assert.True(Util.positiveStrict("Yes"));
    Assert.True(Util.positiveStrict("ano"));
    Assert.False(Util.positiveStrict("y"));
    Assert.Equal("no", Util.YesNo(false));
    Assert.Equal(25.0, Util.percent(1, 4));
    Assert.Equal(300.0, Util.percent(3L, 0L));     // a total below 1 counts as 1
    Assert.Null(Util.EmptyNull(""));
    Assert.Equal(1.0 / 8.0, Arith.Pow(2.0, -3));
    Assert.Equal(2, Arith.Mod(-3, 5));
    Assert.Equal(6L, Arith.GCD(54L, -24L));
    Assert.Equal(6.0, Arith.GCD(54.0, 24.0));
    Assert.Equal(180.0, Arith.RadianToDegree(Math.PI), 12);
  }

  [Fact]
  public void Util_Log_appends_time_stamped_lines_to_the_log_file()
  {
    string file = System.IO.Path.GetTempFileName();
    string saved = Util.logFileName;
    try
    {
      Util.logFileName = file;
      Assert.Equal("first", Util.Log("first"));
      Util.LogFormat("{0:0.0} and {1}", 1.25, "x");
      string[] lines = System.IO.File.ReadAllLines(file).Where(l => l.Length > 0).ToArray();
      Assert.Equal(2, lines.Length);
      Assert.EndsWith(": first", lines[0]);
      Assert.EndsWith(": 1.3 and x", lines[1]);
    }
    finally
    {
      Util.logFileName = saved;
      System.IO.File.Delete(file);
    }
  }

  [Theory]
  [InlineData(1.0, 2.0, 3.0)]
  [InlineData(0.0, 0.0, 1.0)]
  [InlineData(-3.0, 0.5, 0.1)]
  [InlineData(0.2, -4.0, 2.0)]
  public void GetAxes_gives_two_perpendicular_axes_whose_product_is_the_vector_direction(double x, double y, double z)
  {
    var p = new Vector3d(x, y, z);
    Geometry.GetAxes(ref p, out Vector3d p1, out Vector3d p2);
    Assert.Equal(0.0, Vector3d.Dot(p, p1), 12);
    Assert.Equal(0.0, Vector3d.Dot(p, p2), 12);
    Assert.Equal(0.0, Vector3d.Dot(p1, p2), 12);
    Assert.True(p1.Length > 0.0);
    Assert.Equal(Vector3d.Cross(p, p1), p2);
  }

  [Fact]
  public void GetTangents_by_reference_points_north_and_east()
  {
    var p = new Vector3d(1, 0, 0);
    Geometry.GetTangents(ref p, out Vector3d tu, out Vector3d tv);
    Assert.Equal(new Vector3d(0, 0, 1), tu);     // towards +z
    Assert.Equal(new Vector3d(0, -1, 0), tv);
    var pole = new Vector3d(0, 0, 2);
    Geometry.GetTangents(ref pole, out tu, out tv);
    Assert.Equal(Vector3d.UnitX, tu);
  }

  [Fact]
  public void RayTriangleIntersection_returns_t_and_barycentrics_or_negative_infinity()
  {
    Vector3d a = new(0, 0, 0), b = new(1, 0, 0), c = new(0, 1, 0);
    Vector3d p0 = new(0.25, 0.5, -2), p1 = new(0, 0, 1);
    double t = Geometry.RayTriangleIntersection(ref p0, ref p1, ref a, ref b, ref c, out Vector2d uv);
    Assert.Equal(2.0, t, 12);
    Assert.Equal(0.25, uv.X, 12);
    Assert.Equal(0.5, uv.Y, 12);

    Vector3d miss = new(0.8, 0.8, -2);
    Assert.Equal(double.NegativeInfinity, Geometry.RayTriangleIntersection(ref miss, ref p1, ref a, ref b, ref c, out _));
    Vector3d parallel = new(1, 0, 0);
    Assert.Equal(double.NegativeInfinity, Geometry.RayTriangleIntersection(ref p0, ref parallel, ref a, ref b, ref c, out _));

    Vector3 fa = new(0, 0, 0), fb = new(1, 0, 0), fc = new(0, 1, 0);
    Assert.Equal(2.0, Geometry.RayTriangleIntersection(ref p0, ref p1, ref fa, ref fb, ref fc, out _), 6);
  }

  [Fact]
  public void Array_and_colour_conversions()
  {
    Assert.Equal(new[] { 1.0, 2.0, 3.0 }, Geometry.ColorCreate(new Vector3d(1, 2, 3)));
    Vector3d[]? v3 = Geometry.Vector3dArrayFrom(new[] { new Vector3(1, 2, 3) });
    Assert.Equal(new Vector3d(1, 2, 3), Assert.Single(v3!));
    Assert.Equal(new Vector4d(1, 2, 3, 4), Assert.Single(Geometry.Vector4dArrayFrom(new[] { new Vector4(1, 2, 3, 4) })!));
    Assert.Null(Geometry.Vector4dArrayFrom(null));
  }

  [Fact]
  public void BoundingSphere_reports_miss_inside_and_entry()
  {
    var s = new BoundingSphere(2.0);
    Assert.Equal(-1.0, s.Intersect(new Vector3d(0, 5, -10), new Vector3d(0, 0, 1)));
    Assert.Equal(-1.0, s.Intersect(new Vector3d(0, 0, 10), new Vector3d(0, 0, 1)));   // behind
    Assert.Equal(0.0, s.Intersect(Vector3d.Zero, new Vector3d(0, 0, 1)));
    Assert.Equal(8.0, s.Intersect(new Vector3d(0, 0, -10), new Vector3d(0, 0, 1)), 12);
    Assert.Equal(4.0, s.Intersect(new Vector3d(0, 0, -10), new Vector3d(0, 0, 2)), 12);
  }

  [Fact]
  public void Vector_distance_and_swizzles()
  {
    Assert.Equal(25.0, Vector2d.DistanceSquared(new Vector2d(0, 0), new Vector2d(3, 4)));
    var v = new Vector3d(1, 2, 3);
    Assert.Equal(new Vector3d(1, 3, 2), v.Xzy);
    Assert.Equal(new Vector3d(3, 2, 1), v.Zyx);
    v.Yzx = new Vector3d(7, 8, 9);
    Assert.Equal(new Vector3d(9, 7, 8), v);
    Assert.Equal(new Vector2d(8, 9), v.Zx);
  }

  /// <summary>Records every ray <see cref="RayTracing"/> hands to its registerer.</summary>
  sealed class RayLog : AbstractRayRegisterer
  {
    public readonly ConcurrentBag<(RayType Type, int Depth)> Rays = new();

    public override void RegisterRay(RayType rayType, params object[] parameters) =>
      Rays.Add((rayType, parameters[0] is int d ? d : -1));
  }

  [Fact]
  public void A_ray_registerer_sees_every_traced_ray_and_threads_know_their_id()
  {
    IRayScene scene = Scenes.Create("Five balls");
    var log = new RayLog();
    var ids = new ConcurrentBag<int>();
    var rt = new IdRecordingTracing(scene, ids) { rayRegisterer = log };
    var renderer = new SimpleImageSynthesizer { Width = 40, Height = 30 };
    long before = Statistics.allRaysCount;
    FloatImage image = TileRenderer.Render(scene, rt, renderer, new RenderOptions { Threads = 2, TileSize = 8 });

    // One primary ray per pixel at depth 0, hit or miss; secondary rays deeper.
    Assert.Equal(40 * 30, log.Rays.Count(r => r.Depth == 0 && r.Type != AbstractRayRegisterer.RayType.rayVisualizerShadow));
    Assert.Contains(log.Rays, r => r.Depth > 0);
    Assert.Equal(new[] { 0, 1 }, ids.Distinct().Order());
    Assert.True(Statistics.allRaysCount - before >= 40 * 30);

    // Attaching a registerer changes nothing in the picture.
    FloatImage plain = TileRenderer.Render(scene, new RayTracing(scene), new SimpleImageSynthesizer { Width = 40, Height = 30 },
                                           new RenderOptions { Threads = 2, TileSize = 8 });
    Assert.Equal(plain.Data, image.Data);
  }

  sealed class IdRecordingTracing : RayTracing
  {
    readonly ConcurrentBag<int> ids;
    // Both workers meet once, so neither can render every tile alone.
    readonly System.Threading.Barrier meet = new(2);
    [ThreadStatic] static bool met;

    public IdRecordingTracing(IRayScene scene, ConcurrentBag<int> ids) : base(scene) => this.ids = ids;

    public override long GetSample(double x, double y, double[] color)
    {
      if (!met)
      {
        met = true;
        Assert.True(meet.SignalAndWait(TimeSpan.FromSeconds(30)), "the second render thread never started");
      }
      ids.Add(MT.threadID);
      long hash = base.GetSample(x, y, color);
      Assert.Equal(x, MT.doubleX);
      Assert.Equal(y, MT.doubleY);
      return hash;
    }
  }

  /// <summary>A student's sky: overrides GetColor and reads the protected scene, as GrCis allowed.</summary>
  sealed class Sky : DefaultBackground
  {
    public Sky(IRayScene sc) : base(sc)
    {
    }

    public override long GetColor(Vector3d p1, double[] color)
    {
      base.GetColor(p1, color);
      double up = Math.Max(0.0, p1.Normalized().Y);
      for (int b = 0; b < color.Length; b++)
        color[b] += up * (scene?.BackgroundColor?[0] ?? 0.0);
      return 2L;
    }
  }

  [Fact]
  public void A_background_subclass_overrides_GetColor_and_sees_the_scene()
  {
    var scene = new DefaultRayScene { BackgroundColor = new[] { 0.5, 0.25, 0.0 } };
    IBackground sky = new Sky(scene);
    double[] c = new double[3];
    Assert.Equal(2L, sky.GetColor(new Vector3d(0, 1, 0), c));
    Assert.Equal(new[] { 1.0, 0.75, 0.5 }, c);
    var plain = new DefaultBackground((double[]?)Array.Empty<double>());
    plain.GetColor(Vector3d.UnitX, c);
    Assert.Equal(DefaultBackground.DEFAULT_COLOR, c);
  }

  /// <summary>A recursion that adds half the colour of a ray sent straight on, the GrCis way.</summary>
  sealed class HalfThrough : RayRecursion
  {
    public int Calls;

    public HalfThrough(Intersection i, Vector3d dir)
      : base(new[] { 0.1 }, new RayContribution(i, dir, 1.0) { coefficient = new[] { 0.5 } })
    {
    }

    public override long Recursion(RayTracing rt, Intersection i, long hash, int depth, double[] color)
    {
      Calls++;
      return base.Recursion(rt, i, hash, depth, color);
    }
  }

  [Fact]
  public void RayRecursion_adds_its_direct_colour_and_its_rays_scaled_by_their_coefficients()
  {
    // A sphere whose recursion sends the ray on through it; behind it, the background.
    var scene = new DefaultRayScene { BackgroundColor = new[] { 0.2, 0.4, 0.6 } };
    var root = new CSGInnerNode(SetOperation.Union);
    var ball = new Sphere();
    HalfThrough? made = null;
    ball.SetAttribute(PropertyName.RECURSION, (RecursionFunction)((Intersection i, Vector3d dir, double importance, out RayRecursion rr) =>
    {
      rr = made = new HalfThrough(i, dir);
      return 1L;
    }));
    root.InsertChild(ball, Matrix4d.Identity);
    scene.Intersectable = root;
    scene.Camera = new StaticCamera(new Vector3d(0, 0, -5), new Vector3d(0, 0, 1), 40.0);
    scene.Sources = new LinkedList<ILightSource>();
    var rt = new RayTracing(scene) { MaxLevel = 1 };
    rt.Width = 10;
    rt.Height = 10;

    double[] c = new double[3];
    rt.GetSample(5, 5, c);
    // Level 0 hits the front: 0.1 + 0.5 × (level 1 hits the back: 0.1, no deeper rays at MaxLevel).
    Assert.Equal(new[] { 0.15, 0.15, 0.15 }, c.Select(v => Math.Round(v, 12)));
    Assert.Equal(2, made!.Calls + 1);
    var copy = new RayRecursion.RayContribution(made.Rays![0]);
    Assert.Equal(made.Rays[0].origin, copy.p0);
  }
}
