using OpenTK.Mathematics;

namespace Rendering;

/// <summary>A light: how much of it reaches a surface point, and from where.</summary>
public interface ILightSource
{
  /// <summary>
  /// Light position, or null for a light without one (ambient). GrCis added it on 2019-09-29; a light
  /// written before has no position: null, and setting one is ignored (as for an ambient light).
  /// </summary>
  Vector3d? position { get => null; set { } }

  /// <summary>
  /// Intensity reaching the intersection, or null when the point is unlit.
  /// <paramref name="dir"/> points from the point to the light (not normalised); zero for ambient light.
  /// </summary>
  double[]? GetIntensity(Intersection intersection, out Vector3d dir);
}
