using System;
using System.Threading;
using GrCis.Cli.Jobs;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Cli.Animation;

/// <summary>
/// Renders one frame of an animation: moves a worker's scene to the frame's time and renders it
/// with the render settings, the frame number mixed into every pixel's seed (so frames differ and
/// each is reproducible alone, in any order, on any machine). With a shutter, samples are spread
/// over [t, t + shutter / fps] by <see cref="MotionBlurImageFunction"/>.
/// </summary>
public sealed class FrameRenderer
{
  readonly IRayScene scene;
  readonly bool animated;

  public FrameRenderer(IRayScene scene, RenderSettings settings, AnimationTimeline timeline, double shutter = 0.0)
  {
    ArgumentNullException.ThrowIfNull(scene);
    ArgumentNullException.ThrowIfNull(settings);
    ArgumentNullException.ThrowIfNull(timeline);
    this.scene = SceneAnimation.AsTimeDependent(scene);
    animated = SceneCloner.IsTimeDependent(this.scene);
    Settings = settings;
    Timeline = timeline;
    Shutter = shutter;
  }

  public RenderSettings Settings { get; }

  public AnimationTimeline Timeline { get; }

  /// <summary>Fraction of a frame interval the shutter stays open (0 = sharp frames).</summary>
  public double Shutter { get; }

  /// <summary>True when anything in the scene moves with time.</summary>
  public bool IsAnimated => animated;

  /// <summary>A scene for one frame worker: its own clone of the moving parts, the rest shared read-only.</summary>
  public IRayScene CreateWorkerScene() => SceneCloner.CloneForWorker(scene);

  /// <summary>Renders frame <paramref name="frame"/> on <paramref name="workerScene"/> (from <see cref="CreateWorkerScene"/>).</summary>
  public FloatImage Render(IRayScene workerScene, int frame, int threads, Action<RenderProgress>? progress, CancellationToken cancel)
  {
    double time = Timeline.FrameTime(frame);
    if (animated && workerScene is ITimeDependent moving)
      moving.Time = time;

    IImageFunction function;
    if (Shutter > 0.0 && animated)
    {
      // The inner function renders the worker's own clone (MT.scene), which the blur moves per sample.
      var inner = new RayTracing
      {
        DoShadows = Settings.Shadows,
        DoReflections = Settings.Reflections,
        DoRefractions = Settings.Refractions,
      };
      function = new MotionBlurImageFunction(inner) { FrameTime = time, Shutter = Shutter, Fps = Timeline.Fps };
    }
    else
      function = RenderJob.CreateImageFunction(workerScene, Settings);

    ImageSynthesizer synthesizer = RenderJob.CreateSynthesizer(Settings);
    var options = new RenderOptions { Threads = threads, Seed = Settings.Seed, Frame = frame };
    return TileRenderer.Render(workerScene, function, synthesizer, options, progress, cancel);
  }
}
