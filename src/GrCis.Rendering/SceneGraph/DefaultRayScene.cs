using System.Collections.Generic;

namespace Rendering;

/// <summary>A plain, static ray scene: the object scripts fill.</summary>
public class DefaultRayScene : IRayScene
{
  /// <summary>The default background follows <see cref="BackgroundColor"/>, as in GrCis.</summary>
  public DefaultRayScene() => Background = new DefaultBackground(this);

  /// <inheritdoc/>
  public IIntersectable? Intersectable { get; set; }
  /// <inheritdoc/>
  public ITimeDependent? Animator { get; set; }
  /// <inheritdoc/>
  public IBackground? Background { get; set; }
  /// <inheritdoc/>
  public double[]? BackgroundColor { get; set; }
  /// <inheritdoc/>
  public ICamera? Camera { get; set; }
  /// <inheritdoc/>
  public ICollection<ILightSource>? Sources { get; set; }
}
