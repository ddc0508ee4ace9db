using System.Collections.Generic;
using System.Threading;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;
using Rendering.Observation;

namespace GrCis.Rendering.Tests.Execution;

/// <summary>
/// A render's context: its observer sees every ray RayTracing traces, with the right kinds and nesting, and
/// changes nothing in the picture; its counts are this render's own; a thread leaves a context as it found it.
/// </summary>
public class RenderContextTests
{
  /// <summary>Records rays of one thread (a probe-like single-thread use) or counts them (any thread).</summary>
  sealed class Recorder : RayObserver
  {
    public readonly List<(RayKind Kind, int Depth, int Nesting)> Begun = new();
    public long Shaded, Shadows, Blocked, EndedWithHit;
    int open;

    public bool Record { get; init; }

    public override void BeginRay(RayKind kind, int depth, in Vector3d origin, in Vector3d direction)
    {
      Interlocked.Increment(ref Shaded);
      if (Record)
        Begun.Add((kind, depth, open++));
    }

    public override void EndRay(RayKind kind, int depth, in Vector3d origin, in Vector3d direction, Intersection? hit)
    {
      if (Record)
        open--;
      if (hit != null)
        Interlocked.Increment(ref EndedWithHit);
    }

    public override void ShadowRay(in Vector3d origin, in Vector3d direction, bool blocked)
    {
      Interlocked.Increment(ref Shadows);
      if (blocked)
        Interlocked.Increment(ref Blocked);
    }
  }

  static FloatImage Render(IRayScene scene, IImageFunction f, RenderContext? context, int threads = 2) =>
    TileRenderer.Render(scene, f, new SupersamplingImageSynthesizer { Width = 48, Height = 36, Supersampling = 4 },
      new RenderOptions { Threads = threads, TileSize = 8, Seed = 11 }, null, default, context);

  [Theory]
  [InlineData(false, false)]
  [InlineData(true, true)]
  public void Observed_render_has_the_same_pixels_and_the_observer_sees_every_counted_ray(bool transparentShadows, bool fresnel)
  {
    IRayScene scene = TestScenes.BallOnGround(areaLight: false);
    RayTracing Tracer() => new(scene) { TransparentShadows = transparentShadows, FresnelRefraction = fresnel };
    var plainContext = new RenderContext();
    FloatImage plain = Render(scene, Tracer(), plainContext);

    var recorder = new Recorder();
    var observedContext = new RenderContext { Observer = recorder };
    FloatImage observed = Render(scene, Tracer(), observedContext);

    Assert.Equal(plain.Data, observed.Data);
    Assert.Equal(plainContext.Rays, observedContext.Rays);
    Assert.Equal(plainContext.Hits, observedContext.Hits);
    Assert.Equal(observedContext.Rays, recorder.Shaded + recorder.Shadows);
    Assert.Equal(observedContext.Hits, recorder.EndedWithHit + recorder.Blocked);
    // The ball (Kt 0.5) blocks the light, or with transparent shadows lets half of it through.
    Assert.True(transparentShadows ? recorder.Blocked == 0 : recorder.Blocked > 0 && recorder.Blocked < recorder.Shadows,
      $"{recorder.Blocked} of {recorder.Shadows} shadow rays blocked");
  }

  [Fact]
  public void Rays_of_one_sample_arrive_nested_with_their_kinds()
  {
    // The glass ball at the image centre: the primary ray spawns a mirrored and a refracted ray.
    IRayScene scene = TestScenes.BallOnGround(areaLight: false);
    var tracer = new RayTracing(scene);
    tracer.Width = 48;
    tracer.Height = 36;
    var recorder = new Recorder { Record = true };
    using (new RenderContext { Observer = recorder }.Enter())
      tracer.GetSample(24.5, 18.5, new double[3]);

    Assert.Equal((RayKind.Primary, 0, 0), recorder.Begun[0]);
    Assert.Contains((RayKind.Reflected, 1, 1), recorder.Begun);
    Assert.Contains((RayKind.Refracted, 1, 1), recorder.Begun);
    Assert.DoesNotContain(recorder.Begun, r => r.Kind == RayKind.Primary && r.Depth > 0);
    Assert.All(recorder.Begun, r => Assert.Equal(r.Depth, r.Nesting));
    Assert.True(recorder.Shadows > 0);
  }

  [Fact]
  public void Ray_casting_reports_one_primary_ray_per_sample()
  {
    IRayScene scene = TestScenes.BallOnGround(areaLight: false);
    var recorder = new Recorder();
    var context = new RenderContext { Observer = recorder };
    Render(scene, new RayCasting(scene), context);
    Assert.Equal(48L * 36 * 4, recorder.Shaded);
    Assert.Equal(context.Rays, recorder.Shaded);
    Assert.Equal(0, recorder.Shadows);
  }

  [Fact]
  public void Each_render_counts_its_own_rays_and_hits_and_adds_them_to_GrCis_counters_once()
  {
    IRayScene scene = TestScenes.BallOnGround(areaLight: true);
    var one = new RenderContext();
    Render(scene, new RayTracing(scene), one, threads: 1);
    long before = Interlocked.Read(ref Intersection.countRays), hitsBefore = Interlocked.Read(ref Intersection.countIntersections);
    var three = new RenderContext();
    Render(scene, new RayTracing(scene), three, threads: 3);
    long after = Interlocked.Read(ref Intersection.countRays), hitsAfter = Interlocked.Read(ref Intersection.countIntersections);

    Assert.True(one.Rays > 48 * 36 * 4);
    Assert.Equal(one.Rays, three.Rays);            // the count of a render does not depend on threads
    Assert.True(after - before >= three.Rays);     // other tests may render at the same time
    Assert.Equal(one.Hits, three.Hits);
    Assert.True(three.Hits > 0 && hitsAfter - hitsBefore >= three.Hits);
  }

  [Fact]
  public void Leaving_a_context_restores_the_thread_and_counts_what_was_traced_inside()
  {
    IRayScene scene = TestScenes.BallOnGround(areaLight: false);
    var tracer = new RayTracing(scene) { Width = 48, Height = 36 };
    var outer = new Recorder();
    var inner = new Recorder();
    var outerContext = new RenderContext { Observer = outer };
    var innerContext = new RenderContext { Observer = inner };
    using (outerContext.Enter())
    {
      using (innerContext.Enter())
        tracer.GetSample(24.5, 18.5, new double[3]);
      long innerSeen = inner.Shaded;
      tracer.GetSample(10.5, 30.5, new double[3]);
      Assert.Equal(innerSeen, inner.Shaded);
    }
    tracer.GetSample(10.5, 30.5, new double[3]);

    Assert.True(inner.Shaded > 1 && outer.Shaded > 0);
    Assert.Equal(inner.Shaded + inner.Shadows, innerContext.Rays);
    // The outer scope's count includes the inner one (same thread, nested); nothing after it is counted.
    Assert.Equal(inner.Shaded + inner.Shadows + outer.Shaded + outer.Shadows, outerContext.Rays);
  }

  [Fact]
  public void Each_render_prepares_its_scene_in_its_own_context_and_the_function_keeps_no_snapshot()
  {
    IRayScene scene = TestScenes.BallOnGround(areaLight: false);
    var tracer = new RayTracing(scene);
    var first = new RenderContext();
    var second = new RenderContext();
    FloatImage a = Render(scene, tracer, first);
    global::Rendering.Accel.PreparedScene? firstSnapshot = tracer.LastPrepared;
    FloatImage b = Render(scene, tracer, second);

    Assert.Equal(a.Data, b.Data);
    Assert.NotNull(firstSnapshot);
    Assert.Same(firstSnapshot, first.Queries.For(scene.Intersectable!));
    Assert.Same(tracer.LastPrepared, second.Queries.For(scene.Intersectable!));
    Assert.NotSame(firstSnapshot, tracer.LastPrepared);   // a new render starts from a fresh snapshot

    // Outside any render a thread uses queries of its own, and a context's queries are back after its scope.
    var probe = new RenderContext();
    using (probe.Enter())
      tracer.GetSample(24.5, 18.5, new double[3]);
    Assert.Same(tracer.LastPrepared, probe.Queries.For(scene.Intersectable!));
  }
}
