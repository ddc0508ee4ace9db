using System;
using OpenTK.Mathematics;

// Not in namespace Rendering: GrCis's 049 skeleton has students declare Rendering.DistributedRayTracing
// themselves, and scripts import this namespace only while no module declares a class of the same name.
namespace Rendering.Distributed;

/// <summary>
/// Distributed (Cook-style) ray tracing, the 049 homework's image function: Whitted ray tracing whose
/// reflected and refracted rays are sampled from the Phong lobe of the material's exponent
/// <see cref="PhongMaterial.H"/> around the ideal direction (glossy reflection and translucency), with soft
/// shadows from area lights (<see cref="RectangleLightSource"/>, <see cref="SphereLightSource"/>) and depth of
/// field from a <see cref="ThinLensCamera"/>. Every random choice is stratified over the pixel's samples
/// (<see cref="MT.rank"/> of <see cref="MT.total"/>, the worker's <see cref="Sampler"/>), so n×n supersampling is what makes the
/// effects smooth: use 16 or more samples per pixel.
/// </summary>
/// <remarks>
/// Each sampled ray keeps the weight Whitted gives the ideal ray (ks for reflection, kt for refraction): the lobe
/// is normalised, so it blurs what the mirror would show without adding or losing light, except the part of the
/// lobe that falls below the surface (no ray is traced there).
/// </remarks>
[Serializable]
public class DistributedRayTracing : MonteCarloRayTracing
{
  /// <summary>Sample reflected rays from the Phong lobe (false: ideal mirror, as Whitted).</summary>
  public bool GlossyReflections = true;

  /// <summary>Sample refracted rays from the Phong lobe (false: ideal refraction).</summary>
  public bool GlossyRefractions = true;

  /// <summary>Lobes with an exponent at or above this are treated as ideal (narrower than the pixel footprint of usual scenes).</summary>
  public int IdealExponent = 100000;

  /// <summary>Distributed ray tracing of <paramref name="sc"/>, with glossy reflections and refractions on and Whitted's other defaults.</summary>
  /// <param name="sc">The scene, or null to render the current scene (<see cref="MT.scene"/>).</param>
  public DistributedRayTracing(IRayScene? sc = null) : base(sc)
  {
  }

  /// <inheritdoc/>
  public override void CopySettingsFrom(RayCasting source)
  {
    base.CopySettingsFrom(source);
    if (source is not DistributedRayTracing d)
      return;
    GlossyReflections = d.GlossyReflections;
    GlossyRefractions = d.GlossyRefractions;
    IdealExponent = d.IdealExponent;
  }

  /// <summary>
  /// With <see cref="GlossyReflections"/> and a <see cref="PhongMaterial"/> whose H is below <see cref="IdealExponent"/>, a
  /// direction from the cos^H lobe around <paramref name="mirror"/>; false when it points to the other side of the
  /// surface than the mirror direction. Otherwise the mirror direction itself.
  /// </summary>
  protected internal override bool ReflectionDirection(Intersection i, Vector3d mirror, int depth, out Vector3d direction) =>
    Lobe(GlossyReflections, i, mirror, SampleDimension.GlossyReflection, depth, out direction);

  /// <summary>
  /// With <see cref="GlossyRefractions"/> and a <see cref="PhongMaterial"/> whose H is below <see cref="IdealExponent"/>, a
  /// direction from the cos^H lobe around <paramref name="refracted"/>; false when it points to the other side of the
  /// surface than the ideal direction. Otherwise the ideal direction itself.
  /// </summary>
  protected internal override bool RefractionDirection(Intersection i, Vector3d refracted, int depth, out Vector3d direction) =>
    Lobe(GlossyRefractions, i, refracted.Normalized(), SampleDimension.GlossyRefraction, depth, out direction);

  /// <summary>A direction from the cos^H lobe around <paramref name="ideal"/>, on the same side of the surface; false when it falls on the other side.</summary>
  bool Lobe(bool glossy, Intersection i, Vector3d ideal, SampleDimension dimension, int depth, out Vector3d direction)
  {
    direction = ideal;
    if (!glossy || i.Material is not PhongMaterial m || m.H >= IdealExponent)
      return true;
    VertexSampler.Get2D(dimension, depth, out double u, out double v);
    direction = SampleWarp.PowerCosine(u, v, ideal.Normalized(), Math.Max(m.H, 0));
    // A direction that leaves on the other side of the surface than the ideal one carries no light here.
    return Vector3d.Dot(direction, i.Normal) * Vector3d.Dot(ideal, i.Normal) > 0.0;
  }
}
