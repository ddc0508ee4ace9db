using System;
using System.Collections.Generic;
using System.Linq;
using System.Threading;
using System.Threading.Tasks;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;
using GrCis.Hosting;

namespace GrCis.Interactive.Tests;

public class RenderSessionTests
{
  static readonly RenderSettings Small = new() { Width = 96, Height = 64, SamplesPerPixel = 4, TileSize = 16, Threads = 3, Seed = 7 };

  /// <summary>What `grcis render` computes: TileRenderer over a fresh job with the same settings.</summary>
  static FloatImage Reference(RenderSettings s, bool glass = false)
  {
    RenderJob job = RenderJob.Create(TestScenes.SphereOnPlane(glass), s);
    return TileRenderer.Render(job.Scene, job.ImageFunction, job.Renderer, s.ToRenderOptions());
  }

  [Fact]
  public async Task Render_delivers_coarse_and_final_previews_and_the_tile_renderer_image()
  {
    using var session = new RenderSession(RenderJob.Create(TestScenes.SphereOnPlane(), Small));
    var previews = new List<RenderPreviewEventArgs>();
    RenderResult? completed = null;
    session.PreviewReady += (_, e) => { lock (previews) previews.Add(e); };
    session.Completed += (_, e) => completed = e.Result;

    RenderResult result = await session.Start();

    Assert.True(result.Succeeded);
    Assert.Same(result, completed);
    Assert.True(previews.Count >= 2, $"only {previews.Count} previews");
    Assert.Equal(PreviewPass.Coarse, previews[0].Pass);
    Assert.Equal(PreviewPass.Final, previews[^1].Pass);
    Assert.Equal(Enumerable.Range(0, previews.Count), previews.Select(p => p.Sequence));
    Assert.Equal(Reference(Small).Data, result.Image.Data);
    Assert.Equal(result.Image.Data, previews[^1].Image.Data);
  }

  [Fact]
  public async Task Coarse_preview_fills_each_block_with_its_corner_pixel_final_value()
  {
    using var session = new RenderSession(RenderJob.Create(TestScenes.SphereOnPlane(), Small)) { CoarseBlock = 8 };
    FloatImage? coarse = null;
    session.PreviewReady += (_, e) => { if (e.Pass == PreviewPass.Coarse) coarse = e.Image; };
    FloatImage final = (await session.Start()).Image;

    Assert.NotNull(coarse);
    for (int y = 0; y < Small.Height; y++)
      for (int x = 0; x < Small.Width; x++)
        Assert.Equal(final.GetPixel(x / 8 * 8, y / 8 * 8), coarse!.GetPixel(x, y));
  }

  [Fact]
  public async Task Same_image_for_one_thread_and_many_and_with_glass()
  {
    RenderSettings one = Small with { Threads = 1 };
    using var a = new RenderSession(RenderJob.Create(TestScenes.SphereOnPlane(glass: true), one));
    using var b = new RenderSession(RenderJob.Create(TestScenes.SphereOnPlane(glass: true), Small with { Threads = 4 }));
    float[] ia = (await a.Start()).Image.Data, ib = (await b.Start()).Image.Data;
    Assert.Equal(ia, ib);
    Assert.Equal(Reference(Small, glass: true).Data, ia);
  }

  [Fact]
  public async Task Stop_after_five_tiles_keeps_exactly_those_tiles()
  {
    RenderSettings s = Small with { Threads = 1 };
    using var session = new RenderSession(RenderJob.Create(TestScenes.SphereOnPlane(), s));
    // One thread runs tiles in order and checks for a stop between tiles: exactly five finish.
    session.ProgressChanged += (_, e) => { if (e.Progress.TilesDone == 5) session.Stop(); };

    RenderResult result = await session.Start();

    Assert.True(result.Cancelled);
    Assert.Null(result.Error);
    Assert.Equal(5, result.FinishedTiles.Count);
    Assert.Equal(5, result.Statistics.TilesDone);
    Assert.Equal(24, result.Statistics.TilesTotal);

    FloatImage full = Reference(s);
    var done = new HashSet<(int, int)>();
    foreach (Tile t in result.FinishedTiles)
      for (int y = t.Y1; y < t.Y2; y++)
        for (int x = t.X1; x < t.X2; x++)
          done.Add((x, y));
    Assert.Equal(5 * 16 * 16, done.Count);
    for (int y = 0; y < s.Height; y++)
      for (int x = 0; x < s.Width; x++)
        Assert.Equal(done.Contains((x, y)) ? full.GetPixel(x, y) : new double[3], result.Image.GetPixel(x, y));
  }

  [Fact]
  public async Task Statistics_count_rays_and_describe_the_render()
  {
    using var session = new RenderSession(RenderJob.Create(TestScenes.SphereOnPlane(), Small));
    RenderStatistics st = (await session.Start()).Statistics;
    Assert.Equal(96, st.Width);
    Assert.Equal(64, st.Height);
    Assert.Equal(3, st.Threads);
    Assert.Equal(4, st.SamplesPerPixel);
    // At least one primary ray per sample; the mirror sphere and the lights add more.
    Assert.True(st.Rays > 96 * 64 * 4, $"rays {st.Rays}");
    Assert.InRange(st.Intersections, 1, st.Rays);
    Assert.Contains("96x64", st.ToString());
  }

  [Fact]
  public async Task Long_render_previews_at_least_once_a_second()
  {
    var scene = TestScenes.PlaneAt(5);
    var slow = new SlowFunction(TimeSpan.FromMilliseconds(1), new RayTracing(scene));
    RenderSettings s = new() { Width = 40, Height = 30, TileSize = 40, Threads = 1 };
    using var session = new RenderSession(RenderJob.Create(scene, s, slow)) { PreviewInterval = TimeSpan.FromMilliseconds(250) };
    var times = new List<(PreviewPass Pass, TimeSpan At)>();
    var clock = System.Diagnostics.Stopwatch.StartNew();
    session.PreviewReady += (_, e) => { lock (times) times.Add((e.Pass, clock.Elapsed)); };

    RenderResult result = await session.Start();

    Assert.True(result.Succeeded);
    Assert.True(result.Statistics.Elapsed > TimeSpan.FromSeconds(1.1), "the render should be long for this test");
    // A single 40×30 tile: every in-between preview came from the timer, not from tile completion.
    Assert.Contains(times, t => t.Pass == PreviewPass.Tiles);
    for (int i = 1; i < times.Count; i++)
      Assert.True(times[i].At - times[i - 1].At < TimeSpan.FromSeconds(1), $"gap before preview {i}");
  }

  [Fact]
  public async Task A_failing_scene_reports_the_error_without_throwing()
  {
    var scene = TestScenes.PlaneAt(5);
    using var session = new RenderSession(RenderJob.Create(scene, new RenderSettings { Width = 16, Height = 16 }, new ThrowingFunction())) { CoarseBlock = 1 };
    RenderResult result = await session.Start();
    Assert.NotNull(result.Error);
    Assert.False(result.Succeeded);
  }

  sealed class SlowFunction : IImageFunction
  {
    readonly TimeSpan delay;
    readonly IImageFunction inner;
    public SlowFunction(TimeSpan delay, IImageFunction inner) { this.delay = delay; this.inner = inner; }
    public double Width { get => inner.Width; set => inner.Width = value; }
    public double Height { get => inner.Height; set => inner.Height = value; }
    public long GetSample(double x, double y, double[] color) { Thread.Sleep(delay); return inner.GetSample(x, y, color); }
  }

  sealed class ThrowingFunction : IImageFunction
  {
    public double Width { get; set; }
    public double Height { get; set; }
    public long GetSample(double x, double y, double[] color) => throw new InvalidOperationException("scene bug");
  }

  [Fact]
  public async Task Counted_render_keeps_the_scripts_opt_in_settings_and_equals_the_cli_image()
  {
    // Statistics wrap plain ray tracing in the instrumented copy; TransparentShadows and FresnelRefraction
    // must survive that copy, or the demo shows another picture than `grcis render`.
    IRayScene scene = TestScenes.SphereOnPlane(glass: true);
    var function = new RayTracing(scene) { TransparentShadows = true, FresnelRefraction = true };
    using var session = new RenderSession(RenderJob.Create(scene, Small, function));

    RenderResult result = await session.Start();

    Assert.True(result.Statistics.Rays > 0);
    FloatImage cli = TileRenderer.Render(scene, function, RenderJob.CreateRenderer(Small), Small.ToRenderOptions());
    FloatImage plain = Reference(Small, glass: true);
    Assert.NotEqual(plain.Data, cli.Data);   // the two settings change this scene
    Assert.Equal(cli.Data, result.Image.Data);
  }

  [Fact]
  public async Task Coarse_pixels_are_not_rendered_twice_so_rays_equal_the_cli_renders()
  {
    RenderJob job = RenderJob.Create(TestScenes.SphereOnPlane(glass: true), Small);
    var cli = new RenderContext();
    FloatImage reference = TileRenderer.Render(job.Scene, job.ImageFunction, job.Renderer, Small.ToRenderOptions(), context: cli);
    using var session = new RenderSession(RenderJob.Create(TestScenes.SphereOnPlane(glass: true), Small)) { CoarseBlock = 8 };
    RenderResult result = await session.Start();
    Assert.Equal(reference.Data, result.Image.Data);
    Assert.Equal(cli.Rays, result.Statistics.Rays);
  }

  static readonly RenderSettings Sixteen = Small with { SamplesPerPixel = 16, Jitter = 1.0 };

  [Fact]
  public async Task Progressive_passes_add_samples_and_end_in_the_cli_image_bit_for_bit()
  {
    RenderJob job = RenderJob.Create(TestScenes.SphereOnPlane(glass: true), Sixteen);
    var cli = new RenderContext();
    FloatImage reference = TileRenderer.Render(job.Scene, job.ImageFunction, job.Renderer, Sixteen.ToRenderOptions(), context: cli);
    using var session = new RenderSession(RenderJob.Create(TestScenes.SphereOnPlane(glass: true), Sixteen)) { Progressive = true };
    var previews = new List<RenderPreviewEventArgs>();
    session.PreviewReady += (_, e) => { lock (previews) previews.Add(e); };

    RenderResult result = await session.Start();

    Assert.True(result.Succeeded);
    Assert.Equal(reference.Data, result.Image.Data);
    Assert.Equal(cli.Rays, result.Statistics.Rays);
    // One pass per sample count of 4×4: 1, 4, 8, then the final 16.
    int[] passes = previews.Where(p => p.Pass == PreviewPass.Samples && p.Samples != null).Select(p => p.Samples!.Value).ToArray();
    Assert.Equal(new[] { 1, 4, 8 }, passes);
    Assert.Equal(PreviewPass.Final, previews[^1].Pass);
    Assert.Equal(result.Image.Data, previews[^1].Image.Data);
    // The noise estimate needs two diagonals; it then shrinks as samples are added.
    RenderPreviewEventArgs eight = previews.Single(p => p.Samples == 8);
    Assert.Null(previews.Single(p => p.Samples == 4).Noise);
    Assert.NotNull(eight.Noise);
    Assert.NotNull(previews[^1].Noise);
    Assert.True(previews[^1].Noise < eight.Noise, $"noise {previews[^1].Noise} at 16 spp, {eight.Noise} at 8");
    Assert.Equal(result.Statistics.Noise, previews[^1].Noise);
    // Each pass's preview is every pixel's mean so far: closer to the final image the more samples it has.
    double Distance(FloatImage a) => a.Data.Zip(result.Image.Data, (u, v) => Math.Abs(u - v)).Average();
    Assert.True(Distance(eight.Image) < Distance(previews.Single(p => p.Samples == 1).Image));
  }

  [Fact]
  public async Task Progressive_render_of_one_thread_or_four_gives_the_same_image()
  {
    using var one = new RenderSession(RenderJob.Create(TestScenes.SphereOnPlane(glass: true), Sixteen with { Threads = 1 })) { Progressive = true };
    using var four = new RenderSession(RenderJob.Create(TestScenes.SphereOnPlane(glass: true), Sixteen with { Threads = 4 })) { Progressive = true };
    Assert.Equal((await one.Start()).Image.Data, (await four.Start()).Image.Data);
  }

  [Fact]
  public async Task Stopped_progressive_render_keeps_every_pixels_mean_so_far()
  {
    RenderSettings s = Sixteen with { Threads = 1 };
    using var session = new RenderSession(RenderJob.Create(TestScenes.SphereOnPlane(), s)) { Progressive = true };
    FloatImage? firstPass = null;
    session.PreviewReady += (_, e) => { if (e.Samples == 1) firstPass = e.Image; };
    // Stop early in the second pass: the first pass covered every pixel with one sample.
    session.ProgressChanged += (_, e) => { if (e.Fraction > 1.0 / 16 + 0.01) session.Stop(); };

    RenderResult result = await session.Start();

    Assert.True(result.Cancelled);
    Assert.NotNull(firstPass);
    FloatImage full = Reference(s);
    // Every pixel has a value (no black holes), some already past the first pass's single sample.
    int changed = 0;
    for (int y = 0; y < s.Height; y++)
      for (int x = 0; x < s.Width; x++)
      {
        double[] kept = result.Image.GetPixel(x, y), first = firstPass!.GetPixel(x, y);
        if (full.GetPixel(x, y).Sum() > 0)
          Assert.True(kept.Sum() > 0, $"pixel {x},{y} lost");
        if (!kept.SequenceEqual(first))
          changed++;
      }
    Assert.InRange(changed, 1, s.Width * s.Height - 1);
  }

  [Fact]
  public async Task Progressive_soft_shadows_of_an_area_light_equal_the_cli_image()
  {
    // The area light stratifies each pixel's points by rank: the passes must give the one-pass strata.
    static IRayScene Scene()
    {
      IRayScene scene = TestScenes.SphereOnPlane();
      scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>(new ILightSource[]
      {
        new AmbientLightSource(0.5),
        new RectangleLightSource(new OpenTK.Mathematics.Vector3d(-3, 4, -3), new OpenTK.Mathematics.Vector3d(2, 0, 0), new OpenTK.Mathematics.Vector3d(0, 0, 2), 1.0),
      });
      return scene;
    }
    RenderJob job = RenderJob.Create(Scene(), Sixteen, new global::Rendering.Distributed.DistributedRayTracing());
    FloatImage reference = TileRenderer.Render(job.Scene, job.ImageFunction, job.Renderer, Sixteen.ToRenderOptions());
    using var session = new RenderSession(RenderJob.Create(Scene(), Sixteen, new global::Rendering.Distributed.DistributedRayTracing())) { Progressive = true };
    Assert.Equal(reference.Data, (await session.Start()).Image.Data);
  }

  [Fact]
  public async Task A_renderer_of_its_own_is_not_split_into_passes()
  {
    // Adaptive supersampling derives from the n×n grid but takes its samples its own way: tiles, its image.
    static RenderJob Job() => RenderJob.Create(TestScenes.SphereOnPlane(), Sixteen, renderer: new AdaptiveSupersamplingJR { Supersampling = 16 });
    RenderJob job = Job();
    FloatImage reference = TileRenderer.Render(job.Scene, job.ImageFunction, job.Renderer, Sixteen.ToRenderOptions());
    using var session = new RenderSession(Job()) { Progressive = true };
    var passes = new List<PreviewPass>();
    session.PreviewReady += (_, e) => { lock (passes) passes.Add(e.Pass); };
    Assert.Equal(reference.Data, (await session.Start()).Image.Data);
    Assert.DoesNotContain(PreviewPass.Samples, passes);
  }
}
