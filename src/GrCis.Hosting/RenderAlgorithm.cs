namespace GrCis.Hosting;

/// <summary>The image function a render uses when the scene script does not choose one (<c>--algorithm</c>).</summary>
public enum RenderAlgorithm
{
  /// <summary>Whitted ray tracing (<see cref="Rendering.RayTracing"/>), GrCis's default.</summary>
  RayTracing,

  /// <summary>Distributed ray tracing (<see cref="Rendering.Distributed.DistributedRayTracing"/>): glossy rays, soft shadows, depth of field.</summary>
  Distributed,

  /// <summary>Monte Carlo path tracing (<see cref="Rendering.PathTracing"/>): global illumination.</summary>
  Path,
}
