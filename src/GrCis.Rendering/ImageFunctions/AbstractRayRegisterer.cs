/// <summary>
/// Receives the rays <see cref="Rendering.RayTracing"/> traces when one is attached to
/// <see cref="Rendering.RayTracing.rayRegisterer"/> (GrCis's 048 demo used it for its ray visualiser).
/// GrCis declared it in the global namespace; so does this port. Parameters by ray type:
/// <list type="bullet">
/// <item><see cref="RayType.rayVisualizerNormal"/>: depth (int), origin, end point (Vector3d) of a ray that hit nothing;</item>
/// <item><see cref="RayType.unknown"/>: depth (int), origin (Vector3d), the hit (Intersection);</item>
/// <item><see cref="RayType.rayVisualizerShadow"/>: the hit point and the light's position (Vector3d), registered while <see cref="Rendering.MT.singleRayTracing"/> is set.</item>
/// </list>
/// </summary>
public abstract class AbstractRayRegisterer
{
  /// <summary>Called by the ray tracer for a ray it traced; what <paramref name="parameters"/> hold depends on <paramref name="rayType"/> (see the class).</summary>
  /// <param name="rayType">The kind of ray.</param>
  /// <param name="parameters">The ray's data, in the order the class lists.</param>
  public abstract void RegisterRay(RayType rayType, params object[] parameters);

  /// <summary>Kinds of rays reported to <see cref="RegisterRay"/>.</summary>
  public enum RayType
  {
    /// <summary>A ray that hit nothing.</summary>
    rayVisualizerNormal,
    /// <summary>A shadow ray towards a light.</summary>
    rayVisualizerShadow,
    /// <summary>GrCis's kind for its own tools; the library never reports it.</summary>
    mapsNormal,
    /// <summary>A ray that hit a surface.</summary>
    unknown,
  }
}
