using System.Collections.Generic;

namespace Rendering;

/// <summary>Everything a ray-based image function needs: geometry, camera, lights, background.</summary>
public interface IRayScene
{
  IIntersectable? Intersectable { get; set; }

  /// <summary>Optional object that receives time first (see AnimatedRayScene).</summary>
  ITimeDependent? Animator { get; set; }

  IBackground? Background { get; set; }

  /// <summary>Plain background colour used when <see cref="Background"/> is null.</summary>
  double[]? BackgroundColor { get; set; }

  ICamera? Camera { get; set; }

  ICollection<ILightSource>? Sources { get; set; }
}
