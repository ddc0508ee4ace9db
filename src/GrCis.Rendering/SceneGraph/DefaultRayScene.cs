using System.Collections.Generic;

namespace Rendering;

/// <summary>A plain, static ray scene: the object scripts fill.</summary>
public class DefaultRayScene : IRayScene
{
  /// <summary>The default background follows <see cref="BackgroundColor"/>, as in GrCis.</summary>
  public DefaultRayScene() => Background = new DefaultBackground(this);

  public IIntersectable? Intersectable { get; set; }
  public ITimeDependent? Animator { get; set; }
  public IBackground? Background { get; set; }
  public double[]? BackgroundColor { get; set; }
  public ICamera? Camera { get; set; }
  public ICollection<ILightSource>? Sources { get; set; }
}
