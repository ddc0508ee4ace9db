using System;
using System.Threading;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Hosting;

/// <summary>
/// Renders one frame of an animation: moves a worker's scene to the frame's time and renders it with what the
/// render plan builds (<see cref="FrameParts"/>), the frame number mixed into every pixel's seed (so frames differ
/// and each is reproducible alone, in any order, on any machine). With a shutter, samples are spread
/// over [t, t + shutter / fps] by <see cref="MotionBlurImageFunction"/>.
/// </summary>
public sealed class FrameRenderer
{
  readonly IRayScene scene;
  readonly bool animated;
  readonly FrameParts parts;

  /// <param name="plan">What precedence decided (<see cref="PreparedRender.Plan"/>, <see cref="RenderJob.Plan"/>): every frame's
  /// function, renderer and options come from it, as a still's do.</param>
  public FrameRenderer(IRayScene scene, RenderPlan plan, AnimationTimeline timeline, double shutter = 0.0)
  {
    ArgumentNullException.ThrowIfNull(scene);
    ArgumentNullException.ThrowIfNull(plan);
    ArgumentNullException.ThrowIfNull(timeline);
    parts = new FrameParts(plan);
    // The script's own objects may be bound to its scene: keep that very scene (no wrapper, no clones).
    this.scene = parts.Sequential ? scene : SceneAnimation.AsTimeDependent(scene);
    animated = SceneCloner.IsTimeDependent(this.scene);
    Timeline = timeline;
    Shutter = shutter;
  }

  /// <summary>True when frames must render one after another (the script's own objects are not copyable).</summary>
  public bool Sequential => parts.Sequential;

  /// <summary>Each frame's function, renderer and options (and the notes about them).</summary>
  public FrameParts Parts => parts;

  /// <summary>The settings after precedence (the plan's).</summary>
  public RenderSettings Settings => parts.Plan.Settings;

  public AnimationTimeline Timeline { get; }

  /// <summary>Fraction of a frame interval the shutter stays open (0 = sharp frames).</summary>
  public double Shutter { get; }

  /// <summary>True when anything in the scene moves with time.</summary>
  public bool IsAnimated => animated;

  /// <summary>A scene for one frame worker: its own clone of the moving parts, the rest shared read-only.</summary>
  public IRayScene CreateWorkerScene() => parts.Sequential ? scene : SceneCloner.CloneForWorker(scene);

  /// <summary>Renders frame <paramref name="frame"/> on <paramref name="workerScene"/> (from <see cref="CreateWorkerScene"/>).</summary>
  public FloatImage Render(IRayScene workerScene, int frame, int threads, Action<RenderProgress>? progress, CancellationToken cancel)
  {
    double time = Timeline.FrameTime(frame);
    if (animated && workerScene is ITimeDependent moving)
      moving.Time = time;

    // With a shutter the inner function renders the worker's own clone (MT.scene), which the blur moves per sample.
    bool blur = Shutter > 0.0 && animated && !parts.Sequential;
    IImageFunction function = parts.CreateFunction(blur ? null : workerScene);
    if (blur)
      function = new MotionBlurImageFunction(function) { FrameTime = time, Shutter = Shutter, Fps = Timeline.Fps };
    ImageSynthesizer synthesizer = parts.CreateSynthesizer();
    RenderOptions options = parts.CreateOptions(frame, threads);
    return FrameRendering.Render(workerScene, function, synthesizer, options, progress, cancel).Image;
  }
}
