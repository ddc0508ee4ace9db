using System.Collections.Generic;

namespace Rendering;

/// <summary>Everything a ray-based image function needs: geometry, camera, lights, background.</summary>
public interface IRayScene
{
  /// <summary>The geometry: the root of the scene graph (usually a <see cref="CSGInnerNode"/>), or null for an empty scene.</summary>
  IIntersectable? Intersectable { get; set; }

  /// <summary>
  /// Optional object that receives time first (see AnimatedRayScene). GrCis added it on 2020-05-12; a scene
  /// written before has none (null) and cannot take one.
  /// </summary>
  ITimeDependent? Animator
  {
    get => null;
    set => OlderScene.Refuse(this, nameof(Animator), value);
  }

  /// <summary>
  /// The colour of rays that hit nothing, or null for <see cref="BackgroundColor"/>. GrCis added it on
  /// 2020-05-09; a scene written before uses its <see cref="BackgroundColor"/> (null) and cannot take one.
  /// </summary>
  IBackground? Background
  {
    get => null;
    set => OlderScene.Refuse(this, nameof(Background), value);
  }

  /// <summary>Plain background colour used when <see cref="Background"/> is null.</summary>
  double[]? BackgroundColor { get; set; }

  /// <summary>The camera that generates the primary rays.</summary>
  ICamera? Camera { get; set; }

  /// <summary>The light sources (null or empty: no lights).</summary>
  ICollection<ILightSource>? Sources { get; set; }
}
