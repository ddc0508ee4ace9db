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
  public abstract void RegisterRay(RayType rayType, params object[] parameters);

  public enum RayType
  {
    rayVisualizerNormal,
    rayVisualizerShadow,
    mapsNormal,
    unknown,
  }
}
