namespace Rendering;

/// <summary>
/// What a sample value is used for. Each dimension (with its instance: a recursion depth, a bounce, a light)
/// gets values of its own, independent of every other, so adding a random decision never shifts the values
/// another one sees. The numbers of the first eight are the purposes <see cref="Strata"/> used before they had
/// names: the correlated multi-jitter sampler hashes them into its patterns, so its images are unchanged.
/// </summary>
public enum SampleDimension
{
  /// <summary>The per-pixel rotation of the supersampling grid's sub-cell order.</summary>
  PixelGrid = 0,

  /// <summary>The point on a thin lens (depth of field).</summary>
  Lens = 1,

  /// <summary>The point on a sphere light (instance: the light's identity).</summary>
  SphereLight = 2,

  /// <summary>A glossy reflection direction of distributed ray tracing (instance: the depth).</summary>
  GlossyReflection = 3,

  /// <summary>A glossy refraction direction of distributed ray tracing (instance: the depth).</summary>
  GlossyRefraction = 4,

  /// <summary>The scattered direction at a path vertex (instance: the bounce).</summary>
  PathDirection = 5,

  /// <summary>The point on the emitter sampled at a path vertex (instance: the bounce).</summary>
  PathLightPoint = 6,

  /// <summary>The point on a rectangle light (instance: the light's identity).</summary>
  RectangleLight = 7,

  /// <summary>Which lobe of the surface a path vertex scatters by (instance: the bounce).</summary>
  PathLobe = 8,

  /// <summary>Russian roulette at a path vertex (instance: the bounce).</summary>
  PathRoulette = 9,

  /// <summary>Which emitter a path vertex samples (instance: the bounce).</summary>
  PathLightPick = 10,
}
