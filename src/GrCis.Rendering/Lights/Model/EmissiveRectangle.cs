using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// An emissive bounded rectangle (a <see cref="Plane"/> with finite bounds) in the light model: a point uniform by
/// area, density per solid angle d²/(area·cos θ_light); it emits on the side its normal points to.
/// </summary>
internal sealed class EmissiveRectangle : ILight
{
  readonly Vector3d corner, edge1, edge2, normal;
  readonly Rgb radiance;
  readonly double area;

  public EmissiveRectangle(in Vector3d corner, in Vector3d edge1, in Vector3d edge2, in Vector3d normal, in Rgb radiance)
  {
    this.corner = corner;
    this.edge1 = edge1;
    this.edge2 = edge2;
    this.normal = normal;
    this.radiance = radiance;
    area = Vector3d.Cross(edge1, edge2).Length;
  }

  public LightKind Kind => LightKind.Area;

  /// <summary>Flux of a one-sided Lambertian emitter: π·area·mean radiance.</summary>
  public double Power => Math.PI * area * radiance.Average;

  public bool SampleLi(in LightContext ctx, double u, double v, out LightSample sample)
  {
    sample = default;
    Vector3d toLight = corner + u * edge1 + v * edge2 - ctx.P;
    double dist2 = toLight.LengthSquared;
    double dist = Math.Sqrt(dist2);
    if (dist <= 1e-9)
      return false;
    Vector3d wi = toLight / dist;
    double cosL = -Vector3d.Dot(normal, wi);
    if (cosL <= 0.0)
      return false;
    sample = new LightSample(radiance, wi, toLight, dist, dist2 / (area * cosL));
    return true;
  }

  public double PdfLi(in LightContext ctx, in Vector3d wi, in Vector3d point, in Vector3d n)
  {
    double cosL = -Vector3d.Dot(n, wi);
    return cosL > 0.0 ? (point - ctx.P).LengthSquared / (area * cosL) : 0.0;
  }

  public Rgb Le(in Vector3d n, in Vector3d direction) => Vector3d.Dot(n, direction) < 0.0 ? radiance : Rgb.Zero;
}
