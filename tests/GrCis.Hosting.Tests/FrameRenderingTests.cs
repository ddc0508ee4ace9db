using System.Collections.Generic;
using System.Threading;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Hosting.Tests;

public class FrameRenderingTests
{
  static IRayScene Ball()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.8, 0.5, 0.2 }, 0.1, 0.6, 0.3, 16));
    root.InsertChild(new Sphere(), Matrix4d.Identity);
    return new DefaultRayScene
    {
      Intersectable = root,
      BackgroundColor = new[] { 0.1, 0.2, 0.3 },
      Camera = new StaticCamera(new Vector3d(0, 0, -5), Vector3d.UnitZ, 40.0),
      Sources = new LinkedList<ILightSource>(new ILightSource[] { new AmbientLightSource(0.5), new PointLightSource(new Vector3d(-5, 5, -5), 1.0) }),
    };
  }

  static readonly RenderSettings Small = new() { Width = 40, Height = 30, SamplesPerPixel = 4, Threads = 2, TileSize = 8, Seed = 3 };

  [Fact]
  public void Statistics_describe_the_render_and_the_image_is_the_tile_renderers()
  {
    IRayScene scene = Ball();
    FrameResult r = FrameRendering.Render(scene, Small.CreateImageFunction(scene), Small.CreateSynthesizer(), Small.ToRenderOptions());
    FloatImage direct = TileRenderer.Render(scene, Small.CreateImageFunction(scene), Small.CreateSynthesizer(), Small.ToRenderOptions());

    Assert.Equal(direct.Data, r.Image.Data);
    Assert.False(r.Cancelled);
    RenderStatistics s = r.Statistics;
    Assert.Equal((40, 30, 4, 2), (s.Width, s.Height, s.SamplesPerPixel, s.Threads));
    Assert.Equal((20, 20), (s.TilesDone, s.TilesTotal));
    // Every primary sample is a ray, each hit adds a shadow ray, and a hit counts once.
    Assert.True(s.Rays > 40 * 30 * 4 && s.Intersections > 0 && s.Intersections < s.Rays, s.ToString());
    Assert.Contains("40x30, 4 spp, 2 threads", s.ToString());
  }

  [Fact]
  public void A_part_renders_only_its_tiles_and_counts_them()
  {
    IRayScene scene = Ball();
    var tiles = new[] { new Tile(0, 0, 8, 8), new Tile(32, 24, 40, 30) };
    FrameResult r = FrameRendering.Render(scene, Small.CreateImageFunction(scene), Small.CreateSynthesizer(), Small.ToRenderOptions() with { Tiles = tiles });
    Assert.Equal((2, 2), (r.Statistics.TilesDone, r.Statistics.TilesTotal));
    Assert.Equal(new double[3], r.Image.GetPixel(20, 15));          // not in a part tile: left black
    Assert.NotEqual(new double[3], r.Image.GetPixel(0, 0));
  }

  [Fact]
  public void A_cancelled_render_says_so()
  {
    IRayScene scene = Ball();
    using var cancel = new CancellationTokenSource();
    cancel.Cancel();
    FrameResult r = FrameRendering.Render(scene, Small.CreateImageFunction(scene), Small.CreateSynthesizer(), Small.ToRenderOptions(), null, cancel.Token);
    Assert.True(r.Cancelled);
    Assert.Equal(0, r.Statistics.TilesDone);
  }
}
