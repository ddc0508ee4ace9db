using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// A spherical light of radius <see cref="radius"/> around <see cref="PointLightSource.position"/>: each sample
/// lights the point from a point of the sphere's visible cap, chosen uniformly by solid angle and stratified over
/// the pixel's samples (<see cref="Strata"/>), so shadows get soft penumbrae. Radius 0 is the point light.
/// Like <see cref="PointLightSource"/> it has no attenuation unless <see cref="Dim"/> is set.
/// </summary>
[Serializable]
public class SphereLightSource : PointLightSource
{
  /// <summary>Radius of the light sphere in world units; 0 (or less) makes it a point light.</summary>
  public double radius;

  /// <summary>Attenuation 1 / (d0 + d1·r + d2·r²) as for <see cref="RectangleLightSource.Dim"/>; null = none.</summary>
  public double[]? Dim;

  /// <summary>A spherical light of the same intensity in all three bands, without attenuation.</summary>
  /// <param name="pos">Centre in world coordinates.</param>
  /// <param name="rad">Radius in world units (<see cref="radius"/>).</param>
  /// <param name="intens">Intensity of each band.</param>
  public SphereLightSource(Vector3d pos, double rad, double intens) : base(pos, intens) => radius = rad;

  /// <summary>A spherical light of the given intensity per band, without attenuation.</summary>
  /// <param name="pos">Centre in world coordinates.</param>
  /// <param name="rad">Radius in world units (<see cref="radius"/>).</param>
  /// <param name="intens">Intensity per band (copied).</param>
  public SphereLightSource(Vector3d pos, double rad, double[] intens) : base(pos, intens) => radius = rad;

  /// <summary>This light's instance of <see cref="SampleDimension.SphereLight"/>: from its position and radius, the same in every clone and run.</summary>
  int Instance()
  {
    Vector3d c = position ?? Vector3d.Zero;
    long h = BitConverter.DoubleToInt64Bits(c.X) * 31 ^ BitConverter.DoubleToInt64Bits(c.Y) * 17 ^
             BitConverter.DoubleToInt64Bits(c.Z) * 7 ^ BitConverter.DoubleToInt64Bits(radius);
    return (int)(h ^ (h >> 32));
  }

  /// <summary>
  /// Light from one point of the sphere, chosen for the current sample: the nearer point of the sphere along a
  /// direction uniform in the cone the sphere subtends. From inside the sphere, or with radius 0, the centre.
  /// Null when the surface faces away from that point; the intensity is attenuated only when <see cref="Dim"/> is set.
  /// </summary>
  /// <param name="intersection">The completed hit to light (its world point and normal are read).</param>
  /// <param name="dir">From the hit point to the chosen light point, not normalised.</param>
  public override double[]? GetIntensity(Intersection intersection, out Vector3d dir)
  {
    Vector3d p = intersection.CoordWorld;
    Vector3d c = position ?? Vector3d.Zero;
    Vector3d toCentre = c - p;
    double dist2 = toCentre.LengthSquared;
    double r2 = radius * radius;
    if (radius <= 0.0 || dist2 <= r2)
      dir = toCentre;
    else
    {
      // A direction in the cone the sphere subtends, then the nearer point of the sphere along it.
      double dist = Math.Sqrt(dist2);
      Vector3d axis = toCentre / dist;
      double cosMax = Math.Sqrt(Math.Max(0.0, 1.0 - r2 / dist2));
      Execution.WorkerContext.Current.Sampler.Get2D(SampleDimension.SphereLight, Instance(), out double u, out double v);
      Vector3d w = SampleWarp.UniformCone(u, v, axis, cosMax);
      double b = Vector3d.Dot(w, toCentre);
      double t = b - Math.Sqrt(Math.Max(0.0, b * b - dist2 + r2));
      dir = w * t;
    }
    if (Vector3d.Dot(dir, intersection.Normal) <= 0.0)
      return null;
    return Attenuated(Dim, dir.Length);
  }
}
