using Rendering;

namespace GrCis.Hosting;

/// <summary>
/// The time range of an animation by the one precedence rule of every front end: each of start, end and frame rate as
/// the user gave it, else the scene script's (CTX_START_ANIM, CTX_END_ANIM, CTX_FPS), else the scene's own
/// <see cref="ITimeDependent"/> range (start and end), else 0 to 10 s at 25 fps (GrCis's defaults).
/// </summary>
public static class AnimationRange
{
  /// <summary>Used when neither the user nor the scene gives a range.</summary>
  public const double DefaultStart = Rendering.Execution.RenderDefaults.AnimationStart, DefaultEnd = Rendering.Execution.RenderDefaults.AnimationEnd,
    DefaultFps = Rendering.Execution.RenderDefaults.Fps;

  /// <param name="from">Start the user gave, or null.</param>
  /// <param name="to">End the user gave, or null.</param>
  /// <param name="fps">Frame rate the user gave, or null.</param>
  /// <param name="timing">What the script asked for (<see cref="PreparedRender.Timing"/>), or null.</param>
  /// <param name="scene">The built scene.</param>
  public static (double Start, double End, double Fps) Resolve(double? from, double? to, double? fps, ISceneTiming? timing, IRayScene scene)
  {
    var own = scene as ITimeDependent;
    return (from ?? timing?.Start ?? own?.Start ?? DefaultStart,
            to ?? timing?.End ?? own?.End ?? DefaultEnd,
            fps ?? timing?.Fps ?? DefaultFps);
  }
}
