using OpenTK.Mathematics;

namespace Rendering;

/// <summary>A light: how much of it reaches a surface point, and from where.</summary>
public interface ILightSource
{
  /// <summary>Light position, or null for a light without one (ambient).</summary>
  Vector3d? position { get; set; }

  /// <summary>
  /// Intensity reaching the intersection, or null when the point is unlit.
  /// <paramref name="dir"/> points from the point to the light (not normalised); zero for ambient light.
  /// </summary>
  double[]? GetIntensity(Intersection intersection, out Vector3d dir);
}
