using System;
using Rendering.Execution;
using Rendering.Imaging;

namespace Rendering.Tests.ClassicScenes;

public class ScenesTests
{
  public static TheoryData<string> SceneNames => new(Scenes.Names);

  [Fact]
  public void Registry_lists_the_eleven_classic_scenes_in_GrCis_order_then_the_049_test_scene()
  {
    Assert.Equal(new[]
    {
      "Five balls", "Hedgehog in the cage", "Flags", "Sphere on the plane", "Two spheres",
      "Sphere flake", "Cubes", "Cylinders", "Circus", "Toroids", "Bezier", "Test scene",
    }, Scenes.Names);
  }

  [Fact]
  public void Default_scene_exists_and_is_Sphere_on_the_plane()
  {
    Assert.Equal("Sphere on the plane", Scenes.DefaultSceneName);
    Assert.True(Scenes.TryGet(Scenes.DefaultSceneName, out _));
    IRayScene sc = Scenes.DefaultScene();
    Assert.NotNull(sc.Intersectable);
    Assert.NotNull(sc.Camera);
    Assert.NotEmpty(sc.Sources!);
  }

  [Theory]
  [InlineData("FiveBalls", "Five balls")]
  [InlineData("SpherePlane", "Sphere on the plane")]
  [InlineData("TwoSpheres", "Two spheres")]
  [InlineData("Cylinders", "Cylinders")]
  [InlineData("Toroids", "Toroids")]
  [InlineData("sphere ON the PLANE", "Sphere on the plane")]
  [InlineData("hedgehog-in-the-cage", "Hedgehog in the cage")]
  [InlineData(" bezier ", "Bezier")]
  public void Lookup_accepts_compact_and_case_insensitive_names(string query, string expected)
  {
    Assert.Equal(expected, Scenes.CanonicalName(query));
    Assert.True(Scenes.TryGet(query, out InitSceneParamDelegate? init));
    Assert.NotNull(init);
  }

  [Fact]
  public void Unknown_scene_name_is_reported_with_the_known_ones()
  {
    Assert.False(Scenes.TryGet("Teapot", out _));
    var e = Assert.Throws<ArgumentException>(() => Scenes.Create("Teapot"));
    Assert.Contains("Five balls", e.Message);
  }

  [Theory]
  [MemberData(nameof(SceneNames))]
  public void Every_scene_renders_small_and_is_not_constant(string name)
  {
    IRayScene scene = Scenes.Create(name, "depth=3");
    var renderer = new SimpleImageSynthesizer { Width = 64, Height = 48 };
    FloatImage image = TileRenderer.Render(scene, new RayTracing(scene), renderer, new RenderOptions());

    float[] d = image.Data;
    bool varies = false;
    for (int i = 3; i < d.Length && !varies; i++)
      varies = d[i] != d[i % 3];
    Assert.True(varies, $"Scene '{name}' rendered a constant image.");
    foreach (float v in d)
      Assert.True(float.IsFinite(v) && v >= 0.0f, $"Scene '{name}' produced an invalid sample {v}.");
  }

  [Fact]
  public void Scene_parameters_are_parsed()
  {
    // A one-level flake is a single sphere; the default depth 5 has 2801.
    ISceneNode one = Scenes.flake(1, 0.4);
    Assert.Single(one.Children);
    ISceneNode two = Scenes.flake(2, 0.4);
    Assert.Equal(8, two.Children.Count);

    IRayScene glass = Scenes.Create("Two spheres", "n=1.33");
    var root = (ISceneNode)glass.Intersectable!;
    var first = System.Linq.Enumerable.First(root.Children);
    var pm = Assert.IsType<PhongMaterial>(first.GetLocalAttribute(PropertyName.MATERIAL));
    Assert.Equal(1.33, pm.n, 12);
    Assert.Equal(0.9, pm.Kt, 12);
  }
}
