using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// An emissive sphere (a <see cref="Sphere"/> placed by a similarity) in the light model: a direction uniform in the
/// cone it subtends, density 1/(2π(1 − cos θmax)) with sin θmax = r/d; nothing to a point inside or on it.
/// </summary>
internal sealed class EmissiveSphere : ILight
{
  /// <summary>
  /// Points whose squared distance from the centre is within this relative margin of r² count as on it: they see
  /// none of its outer side, so they get no light sample and its rays no MIS weight against one.
  /// </summary>
  const double OnSphere = 1e-9;

  readonly Vector3d centre;
  readonly double radius;
  readonly Rgb radiance;

  public EmissiveSphere(in Vector3d centre, double radius, in Rgb radiance)
  {
    this.centre = centre;
    this.radius = radius;
    this.radiance = radiance;
  }

  public LightKind Kind => LightKind.Area;

  /// <summary>Flux of a Lambertian emitter: π·4πr²·mean radiance.</summary>
  public double Power => Math.PI * 4.0 * Math.PI * radius * radius * radiance.Average;

  public bool SampleLi(in LightContext ctx, double u, double v, out LightSample sample)
  {
    sample = default;
    if (!Cone(ctx.P, out Vector3d axis, out double cosMax, out double solidAngle))
      return false;
    // A direction uniform in the cone, then the near side of the sphere along it.
    Vector3d wi = SampleWarp.UniformCone(u, v, axis, cosMax);
    Vector3d toCentre = centre - ctx.P;
    double b = Vector3d.Dot(wi, toCentre);
    double miss = (toCentre - b * wi).LengthSquared;   // squared distance of the ray from the centre
    double dist = b - Math.Sqrt(Math.Max(0.0, radius * radius - miss));
    if (!(dist > 1e-9))
      return false;
    sample = new LightSample(radiance, wi, wi * dist, dist, 1.0 / solidAngle);
    return true;
  }

  public double PdfLi(in LightContext ctx, in Vector3d wi, in Vector3d point, in Vector3d normal) =>
    Cone(ctx.P, out _, out _, out double solidAngle) ? 1.0 / solidAngle : 0.0;

  public Rgb Le(in Vector3d normal, in Vector3d direction) => Vector3d.Dot(normal, direction) < 0.0 ? radiance : Rgb.Zero;

  /// <summary>The cone the sphere subtends from <paramref name="x"/>: its axis, the cosine of its half-angle, its solid angle; false from inside or on it.</summary>
  bool Cone(in Vector3d x, out Vector3d axis, out double cosMax, out double solidAngle)
  {
    Vector3d toCentre = centre - x;
    double d2 = toCentre.LengthSquared;
    double r2 = radius * radius;
    if (!(d2 > r2 * (1.0 + OnSphere)))
    {
      axis = default;
      cosMax = solidAngle = 0.0;
      return false;
    }
    axis = toCentre / Math.Sqrt(d2);
    double sin2 = r2 / d2;
    cosMax = Math.Sqrt(1.0 - sin2);
    solidAngle = 2.0 * Math.PI * sin2 / (1.0 + cosMax);   // 2π(1 − cos θmax) without cancellation for small spheres
    return true;
  }
}
