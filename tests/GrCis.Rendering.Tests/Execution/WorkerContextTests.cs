using System;
using System.Linq;
using System.Reflection;
using System.Runtime.InteropServices;
using System.Threading;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;
using GrCis.Rendering.Tests.ImageFunctions;

namespace GrCis.Rendering.Tests.Execution;

/// <summary>
/// The worker context: the one per-thread state of the library, built in one place for every kind of worker; a
/// pixel is the same whether the tile renderer, progressive passes or a probe-like worker takes it, with every sampler.
/// </summary>
public class WorkerContextTests
{
  public static TheoryData<SamplerKind> Kinds => new() { SamplerKind.CorrelatedMultiJitter, SamplerKind.Independent, SamplerKind.Sobol };

  [Fact]
  public void The_worker_context_is_the_only_thread_static_of_the_rendering_assembly()
  {
    // Per-thread state travels in the worker context; GrCis's MT statics are properties over it.
    Assembly rendering = typeof(WorkerContext).Assembly;
    string[] allowed = { "Rendering.Execution.WorkerContext.current" };
    string[] found = rendering.GetTypes()
      .SelectMany(t => t.GetFields(BindingFlags.Static | BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.DeclaredOnly)
        .Where(f => f.IsDefined(typeof(ThreadStaticAttribute)) ||
                    (f.FieldType.IsGenericType && f.FieldType.GetGenericTypeDefinition() == typeof(ThreadLocal<>)))
        .Select(f => $"{t.FullName}.{f.Name}"))
      .ToArray();
    string[] threadLocalInstances = rendering.GetTypes()
      .SelectMany(t => t.GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.DeclaredOnly)
        .Where(f => f.FieldType.IsGenericType && f.FieldType.GetGenericTypeDefinition() == typeof(ThreadLocal<>))
        .Select(f => $"{t.FullName}.{f.Name}"))
      .ToArray();
    Assert.Equal(allowed, found);
    Assert.Empty(threadLocalInstances);
  }

  [Fact]
  public void Begin_makes_a_worker_that_MT_shows_and_gives_the_thread_back_afterwards()
  {
    IRayScene scene = TestScenes.BallOnGround(areaLight: false);
    var function = new RayTracing(scene);
    var renderer = new SimpleImageSynthesizer();
    WorkerContext outer = WorkerContext.Current;
    MT.seed = 1;
    MT.scene = null;
    MT.time = 2.5;
    var context = new RenderContext();
    using var cts = new CancellationTokenSource();
    using (WorkerContext.Scope worker = WorkerContext.Begin(context, scene, function, renderer,
             new RenderOptions { Seed = 42, Frame = 3, Sampler = SamplerKind.Sobol }, cts.Token, threadID: 5))
    {
      Assert.Same(worker.Context, WorkerContext.Current);
      Assert.Equal(42L, MT.seed);
      Assert.Equal(3, MT.frame);
      Assert.Equal(5, MT.threadID);
      Assert.Equal(2.5, MT.time);   // the scene time carries over from the thread that begins the worker
      Assert.Same(scene, MT.scene);
      Assert.Same(function, MT.imageFunction);
      Assert.Same(renderer, MT.renderer);
      Assert.Equal(SamplerKind.Sobol, WorkerContext.Current.Sampler.Kind);
      Assert.Equal(cts.Token, Interruption.Current);
      MT.StartPixel(24, 18, 1);
      Assert.Equal(24, WorkerContext.Current.Sampler.X);
      function.GetSample(24.5, 18.5, new double[3]);
    }
    Assert.Same(outer, WorkerContext.Current);
    Assert.Equal(1L, MT.seed);
    Assert.Null(MT.scene);
    Assert.Equal(CancellationToken.None, Interruption.Current);
    Assert.True(context.Rays > 0, "the worker's rays count for its render");
  }

  /// <summary>Records the scene time its workers see.</summary>
  sealed class TimeRecorder : IImageFunction
  {
    public readonly System.Collections.Concurrent.ConcurrentBag<double> Times = new();

    public double Width { get; set; }

    public double Height { get; set; }

    public long GetSample(double x, double y, double[] color)
    {
      Times.Add(MT.time);
      return 0L;
    }
  }

  [Theory]
  [InlineData(1)]
  [InlineData(3)]
  public void Every_worker_sees_the_scene_time_of_the_thread_that_started_the_render(int threads)
  {
    IRayScene scene = TestScenes.BallOnGround(areaLight: false);
    var recorder = new TimeRecorder();
    double before = MT.time;
    MT.time = 1.75;
    try
    {
      TileRenderer.Render(scene, recorder, new SimpleImageSynthesizer { Width = 16, Height = 16 },
        new RenderOptions { Threads = threads, TileSize = 4 });
    }
    finally
    {
      MT.time = before;
    }
    Assert.Equal(256, recorder.Times.Count);
    Assert.All(recorder.Times, t => Assert.Equal(1.75, t));
  }

  static bool BitIdentical(FloatImage a, FloatImage b) =>
    MemoryMarshal.AsBytes(a.Data.AsSpan()).SequenceEqual(MemoryMarshal.AsBytes(b.Data.AsSpan()));

  static FloatImage Render(IRayScene scene, IImageFunction f, SamplerKind kind, int threads, int tileSize, int spp = 16) =>
    TileRenderer.Render(scene, f, new SupersamplingImageSynthesizer { Width = 20, Height = 20, Supersampling = spp },
      new RenderOptions { Threads = threads, TileSize = tileSize, Seed = 9, Sampler = kind });

  [Theory]
  [MemberData(nameof(Kinds))]
  public void Path_traced_image_is_the_same_on_any_threads_and_tiles_with_each_sampler(SamplerKind kind)
  {
    IRayScene scene = CornellScene.Create(diffuse: false);
    FloatImage one = Render(scene, new PathTracing(), kind, threads: 1, tileSize: 20);
    FloatImage three = Render(scene, new PathTracing(), kind, threads: 3, tileSize: 3);
    Assert.True(one.Data.Distinct().Count() > 100, "the image should not be flat");
    Assert.True(BitIdentical(one, three));
  }

  [Fact]
  public void Samplers_give_different_path_traced_images_of_the_same_mean()
  {
    IRayScene scene = CornellScene.Create(diffuse: true);
    double[] means = new double[3];
    FloatImage[] images = new FloatImage[3];
    foreach (SamplerKind kind in new[] { SamplerKind.CorrelatedMultiJitter, SamplerKind.Independent, SamplerKind.Sobol })
    {
      images[(int)kind] = Render(scene, new PathTracing(), kind, threads: 2, tileSize: 8, spp: 64);
      means[(int)kind] = images[(int)kind].Data.Average(v => (double)v);
    }
    Assert.False(BitIdentical(images[0], images[1]));
    Assert.False(BitIdentical(images[0], images[2]));
    // 400 pixels of 64 samples: the means agree within a few percent.
    Assert.InRange(means[1] / means[0], 0.95, 1.05);
    Assert.InRange(means[2] / means[0], 0.95, 1.05);
  }

  [Theory]
  [MemberData(nameof(Kinds))]
  public void Tile_progressive_passes_and_a_probe_worker_give_the_same_pixel(SamplerKind kind)
  {
    IRayScene scene = CornellScene.Create(diffuse: false);
    var f = new PathTracing();
    var synth = new SupersamplingImageSynthesizer { Width = 20, Height = 20, Supersampling = 16 };
    var options = new RenderOptions { Threads = 2, TileSize = 8, Seed = 9, Sampler = kind };
    FloatImage tiled = TileRenderer.Render(scene, f, synth, options);

    foreach ((int x, int y) in new[] { (10, 10), (3, 17), (15, 4) })
    {
      // A probe's worker: one pixel, on this thread.
      var probed = new double[3];
      using (WorkerContext.Begin(null, scene, f, synth, options))
        synth.PixelLinear(x, y, probed);

      // Progressive passes: samples [0,1), [1,4), [4,16) in separate calls, each from its own worker.
      var sum = new double[3];
      var odd = new double[3];
      var scratch = new double[3];
      foreach ((int first, int end) in new[] { (0, 1), (1, 4), (4, 16) })
        using (WorkerContext.Begin(new RenderContext(), scene, f, synth, options))
          synth.AccumulateSamples(x, y, first, end, scratch, sum, odd);
      var passes = new double[3];
      synth.FinishPixel(sum, passes);

      for (int b = 0; b < 3; b++)
      {
        Assert.Equal(tiled[x, y, b], (float)probed[b]);
        Assert.Equal(probed[b], passes[b], 12);
      }
    }
  }
}
