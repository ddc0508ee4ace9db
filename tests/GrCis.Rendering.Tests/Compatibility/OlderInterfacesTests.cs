using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Rendering.Tests.Compatibility;

/// <summary>
/// Classes written against an older GrCis, before members were added to the interfaces they implement
/// (<c>ILightSource.position</c> and <c>ISolid.GetBoundingBox</c> on 2019-09-29, <c>IRayScene.Background</c> on
/// 2020-05-09, <c>IRayScene.Animator</c> on 2020-05-12): they compile unchanged and render as GrCis rendered them.
/// </summary>
public class OlderInterfacesTests
{
  // ---------------------------------------------------------------- a student's classes, as written in 2018

  /// <summary>A point light of 2018: GetIntensity only, no position.</summary>
  sealed class MyPointLight : ILightSource
  {
    Vector3d pos;
    double[] intensity;

    public MyPointLight(Vector3d p, double i)
    {
      pos = p;
      intensity = new double[] { i, i, i };
    }

    public double[] GetIntensity(Intersection intersection, out Vector3d dir)
    {
      dir = pos - intersection.CoordWorld;
      if (Vector3d.Dot(dir, intersection.Normal) <= 0.0)
        return null!;
      return intensity;
    }
  }

  /// <summary>A unit ball of 2018: Intersect and CompleteIntersection, no bounding box.</summary>
  class MyBall : DefaultSceneNode, ISolid
  {
    public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
    {
      double a = Vector3d.Dot(p1, p1);
      double b = 2.0 * Vector3d.Dot(p0, p1);
      double c = Vector3d.Dot(p0, p0) - 1.0;
      double d = b * b - 4.0 * a * c;
      if (d <= 0.0)
        return null;
      d = Math.Sqrt(d);
      var result = new LinkedList<Intersection>();
      result.AddLast(Hit(p0, p1, (-b - d) / (2.0 * a), true));
      result.AddLast(Hit(p0, p1, (-b + d) / (2.0 * a), false));
      return result;
    }

    Intersection Hit(Vector3d p0, Vector3d p1, double t, bool enter)
    {
      var i = new Intersection(this);
      i.T = t;
      i.Enter = i.Front = enter;
      i.CoordLocal = p0 + t * p1;
      i.NormalLocal = i.CoordLocal;
      return i;
    }

    public override void CompleteIntersection(Intersection inter)
    {
      inter.Normal = Vector3d.TransformNormalInverse(inter.NormalLocal, inter.WorldToLocal).Normalized();
      inter.TextureCoord = new Vector2d(inter.CoordLocal.X, inter.CoordLocal.Y);
    }
  }

  /// <summary>The same ball with the box a 2020 student would add.</summary>
  sealed class MyBoxedBall : MyBall, ISolid
  {
    public void GetBoundingBox(out Vector3d corner1, out Vector3d corner2)
    {
      corner1 = new Vector3d(-1.0);
      corner2 = new Vector3d(1.0);
    }
  }

  /// <summary>A scene class of 2019: no Background, no Animator.</summary>
  sealed class MyScene : IRayScene
  {
    public IIntersectable? Intersectable { get; set; }
    public double[]? BackgroundColor { get; set; }
    public ICamera? Camera { get; set; }
    public ICollection<ILightSource>? Sources { get; set; }
  }

  // ---------------------------------------------------------------- helpers

  static FloatImage Render(IRayScene scene, AccelMode mode = AccelMode.Bvh)
  {
    var renderer = new SimpleImageSynthesizer { Width = 32, Height = 24 };
    return TileRenderer.Render(scene, new RayTracing(scene) { Accel = mode }, renderer, new RenderOptions { Threads = 2, TileSize = 8, Seed = 3 });
  }

  /// <summary>Two balls side by side (a union, so the prepared scene builds a BVH over them) under one light.</summary>
  static DefaultRayScene Balls(Func<ISceneNode> ball, ILightSource light)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 0.8, 0.6, 0.2 }, 0.1, 0.7, 0.2, 16));
    root.InsertChild(ball(), Matrix4d.CreateTranslation(-1.2, 0.0, 0.0));
    root.InsertChild(ball(), Matrix4d.CreateTranslation(1.2, 0.0, 0.0));
    var scene = new DefaultRayScene
    {
      Intersectable = root,
      BackgroundColor = new double[] { 0.1, 0.2, 0.3 },
      Camera = new StaticCamera(new Vector3d(0.0, 0.0, -7.0), Vector3d.UnitZ, 50.0),
    };
    scene.Sources = new List<ILightSource> { new AmbientLightSource(0.1), light };
    return scene;
  }

  static void AssertSame(FloatImage expected, FloatImage actual) => Assert.Equal(expected.Data, actual.Data);

  // ---------------------------------------------------------------- lights

  [Fact]
  public void A_light_written_before_positions_has_none_and_ignores_one_set()
  {
    ILightSource light = new MyPointLight(new Vector3d(0.0, 5.0, -5.0), 1.0);
    Assert.Null(light.position);
    light.position = new Vector3d(1.0, 2.0, 3.0);
    Assert.Null(light.position);
  }

  [Fact]
  public void A_light_written_before_positions_lights_as_the_library_point_light_at_its_place()
  {
    var place = new Vector3d(-3.0, 5.0, -6.0);
    FloatImage theirs = Render(Balls(() => new Sphere(), new MyPointLight(place, 0.9)));
    FloatImage ours = Render(Balls(() => new Sphere(), new PointLightSource(place, 0.9)));
    AssertSame(ours, theirs);
  }

  [Fact]
  public void The_library_point_light_keeps_its_own_position()
  {
    ILightSource light = new PointLightSource(new Vector3d(1.0, 2.0, 3.0), 1.0);
    light.position = new Vector3d(4.0, 5.0, 6.0);
    Assert.Equal(new Vector3d(4.0, 5.0, 6.0), light.position);
  }

  // ---------------------------------------------------------------- solids

  [Fact]
  public void A_solid_written_before_bounding_boxes_answers_the_whole_space()
  {
    ISolid ball = new MyBall();
    ball.GetBoundingBox(out Vector3d c1, out Vector3d c2);
    double p = DefaultSceneNode.INFINITY_PLACEHOLDER;
    Assert.Equal(new Vector3d(-p), c1);
    Assert.Equal(new Vector3d(p), c2);
  }

  [Fact]
  public void A_solid_that_has_its_own_box_keeps_it()
  {
    ISolid ball = new MyBoxedBall();
    ball.GetBoundingBox(out Vector3d c1, out Vector3d c2);
    Assert.Equal((new Vector3d(-1.0), new Vector3d(1.0)), (c1, c2));
    ISolid sphere = new Sphere();
    sphere.GetBoundingBox(out c1, out c2);
    Assert.Equal((new Vector3d(-1.0), new Vector3d(1.0)), (c1, c2));
  }

  [Theory]
  [InlineData(AccelMode.Bvh)]
  [InlineData(AccelMode.None)]
  public void A_solid_written_before_bounding_boxes_is_hit_as_the_same_solid_with_a_box(AccelMode mode)
  {
    var light = new Vector3d(-3.0, 5.0, -6.0);
    FloatImage without = Render(Balls(() => new MyBall(), new PointLightSource(light, 0.9)), mode);
    FloatImage with = Render(Balls(() => new MyBoxedBall(), new PointLightSource(light, 0.9)), mode);
    AssertSame(with, without);

    // Both balls are there: the pixels in front of their centres are not the background.
    var color = new double[3];
    foreach (int x in new[] { 9, 22 })
    {
      without.GetPixel(x, 12, color);
      Assert.NotEqual(new double[] { 0.1f, 0.2f, 0.3f }, color);
    }
  }

  // ---------------------------------------------------------------- scenes

  [Fact]
  public void A_scene_written_before_backgrounds_and_animators_has_neither()
  {
    IRayScene scene = new MyScene();
    Assert.Null(scene.Background);
    Assert.Null(scene.Animator);
    scene.Background = null;
    scene.Animator = null;
    Assert.Null(scene.Background);
  }

  [Fact]
  public void A_scene_written_before_backgrounds_cannot_take_one_and_says_so()
  {
    IRayScene scene = new MyScene();
    var e = Assert.Throws<NotSupportedException>(() => scene.Background = new DefaultBackground(new double[] { 1.0, 0.0, 0.0 }));
    Assert.Contains("MyScene", e.Message);
    Assert.Contains("Background", e.Message);
    Assert.Throws<NotSupportedException>(() => scene.Animator = new AnimatedCSGInnerNode(SetOperation.Union));
  }

  [Fact]
  public void A_scene_written_before_backgrounds_renders_misses_in_its_background_colour()
  {
    DefaultRayScene library = Balls(() => new Sphere(), new PointLightSource(new Vector3d(-3.0, 5.0, -6.0), 0.9));
    var theirs = new MyScene
    {
      Intersectable = library.Intersectable,
      BackgroundColor = library.BackgroundColor,
      Camera = library.Camera,
      Sources = library.Sources,
    };
    FloatImage image = Render(theirs);
    AssertSame(Render(library), image);
    var color = new double[3];
    image.GetPixel(0, 0, color);
    Assert.Equal(new double[] { 0.1f, 0.2f, 0.3f }, color);   // the image stores floats
  }

  // ---------------------------------------------------------------- scene nodes

  [Fact]
  public void A_node_marked_ObjectRoot_is_the_object_space_of_the_nodes_below_it()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    var group = new CSGInnerNode(SetOperation.Union);
    var ball = new Sphere();
    root.InsertChild(group, Matrix4d.CreateTranslation(5.0, 0.0, 0.0));
    group.InsertChild(ball, Matrix4d.CreateTranslation(1.0, 0.0, 0.0));
    Assert.Equal(new Vector3d(6.0, 0.0, 0.0), Vector3d.TransformPosition(Vector3d.Zero, ball.ToObject()));

    group.ObjectRoot = true;   // as GrCis scripts mark it: a flag
    Assert.Equal(new Vector3d(1.0, 0.0, 0.0), Vector3d.TransformPosition(Vector3d.Zero, ball.ToObject()));
    Assert.Equal(Matrix4d.Identity, group.ToObject());
    Assert.Equal(new Vector3d(6.0, 0.0, 0.0), Vector3d.TransformPosition(Vector3d.Zero, ball.ToWorld()));
  }
}
