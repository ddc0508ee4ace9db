namespace GrCis.Hosting;

/// <summary>
/// A scene source that knows the animation range its scene asks for (a script's context
/// <c>Start</c>, <c>End</c>, <c>Fps</c>); read after <see cref="ISceneSource.CreateScene"/>. Null
/// means the scene did not say; <c>grcis animate</c> then falls back to the scene's own
/// <see cref="Rendering.ITimeDependent"/> range and finally to its defaults.
/// </summary>
public interface ISceneTiming
{
  double? Start { get; }

  double? End { get; }

  double? Fps { get; }
}
