using System;
using System.Collections.Generic;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// Every light of a scene in the one light model: the delta lights, which a vertex samples all (as Whitted ray tracing
/// does; no ray can hit them, so they need no MIS), and the lights a ray may also hit, among which the
/// <see cref="LightSampler"/> chooses one by power. The lights are
/// GrCis's light sources (<see cref="GrCisLight"/> for its own types, <see cref="CustomLight"/> for any other;
/// <see cref="AmbientLightSource"/> is left out, as the indirect light it stood for is computed), the emissive
/// rectangles and spheres (<see cref="EmitterSet"/>), any other emissive surface (<see cref="EmissiveSurface"/>, found by
/// rays only) and the background (<see cref="EnvironmentLight"/>). A ray that hits an emitter gets its radiance from here
/// too (<see cref="Emitted"/>), so one model answers both light sampling and hits.
/// Made per worker: the adapters keep buffers.
/// </summary>
internal sealed class SceneLights
{
  readonly Dictionary<ISolid, ILight> surfaces = new(ReferenceEqualityComparer.Instance);
  readonly Dictionary<PhongMaterial, EmissiveSurface> unsampled = new(ReferenceEqualityComparer.Instance);

  /// <summary>True when the background is among the lights sampled.</summary>
  public bool SamplesEnvironment { get; }

  /// <summary>The delta lights, each sampled at every vertex.</summary>
  public ILight[] DeltaLights { get; }

  /// <summary>Chooses the one area or infinite light a vertex samples.</summary>
  public LightSampler Sampler { get; }

  /// <summary>The background as a light (null when there is none to sample).</summary>
  public EnvironmentLight? Environment { get; }

  SceneLights(IRayScene scene, IIntersectable? root, int bands, bool sampleEnvironment)
  {
    var all = new List<ILight>();
    var deltas = new List<ILight>();
    if (scene.Sources is IEnumerable<ILightSource> sources)
      foreach (ILightSource source in sources)
      {
        if (source == null || Accel.SubclassCheck.OverridesNothing(source, typeof(AmbientLightSource)))
          continue;
        deltas.Add((ILight?)GrCisLight.For(source) ?? new CustomLight(source));
      }
    foreach (var (solid, light) in EmitterSet.Of(root).Lights)
    {
      surfaces[solid] = light;
      all.Add(light);
    }
    if (sampleEnvironment && new EnvironmentLight(scene, bands, SceneBounds.Radius(root)) is { Power: > 0.0 } environment)
    {
      Environment = environment;
      all.Add(environment);
    }
    SamplesEnvironment = sampleEnvironment;
    DeltaLights = deltas.ToArray();
    Sampler = new LightSampler(all);
  }

  /// <summary>The lights of <paramref name="scene"/> whose solids lie under <paramref name="root"/>, in their current placement.</summary>
  /// <remarks>The background is a light to sample only when <paramref name="sampleEnvironment"/>; else rays that leave the scene alone find it.</remarks>
  public static SceneLights Of(IRayScene scene, IIntersectable? root, int bands, bool sampleEnvironment) => new(scene, root, bands, sampleEnvironment);

  /// <summary>
  /// Radiance a ray of unit <paramref name="direction"/> gets from the emitter it hit at <paramref name="i"/> (completed),
  /// and the <paramref name="light"/> that answered: the sampled light of that solid, else the hit material's own
  /// <see cref="EmissiveSurface"/>; zero and null when the hit's material has no emission.
  /// </summary>
  public Rgb Emitted(Intersection i, in Vector3d direction, out ILight? light)
  {
    // Only an emissive material emits (a type test first: most hits are not on an emitter).
    if (i.Material is PhongMaterial { Emission: not null } material)
    {
      if (i.Solid != null && surfaces.TryGetValue(i.Solid, out light))
        return light.Le(i.Normal, direction);
      if (!unsampled.TryGetValue(material, out EmissiveSurface? surface))
        unsampled[material] = surface = new EmissiveSurface(material);
      light = surface;
      return surface.Le(i.Normal, direction);
    }
    light = null;
    return Rgb.Zero;
  }

  /// <summary>
  /// The density per solid angle with which light sampling from <paramref name="from"/> (choice included) gives the
  /// ray of unit <paramref name="direction"/> that reached <paramref name="light"/> at <paramref name="point"/>; 0 for a
  /// light never chosen.
  /// </summary>
  public double Pdf(ILight light, in LightContext from, in Vector3d direction, in Vector3d point, in Vector3d normal)
  {
    double pick = Sampler.Probability(light);
    return pick > 0.0 ? pick * light.PdfLi(from, direction, point, normal) : 0.0;
  }

  /// <summary>The same for a ray that left the scene (the background).</summary>
  public double EnvironmentPdf(in LightContext from, in Vector3d direction) =>
    Environment == null ? 0.0 : Sampler.Probability(Environment) * Environment.PdfLi(from, direction, default, default);
}
