using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// An emissive bounded rectangle (a <see cref="Plane"/> with finite bounds) in the light model; it emits on the side its
/// normal points to. A true rectangle (perpendicular edges) is sampled uniformly by the solid angle it subtends
/// (<see cref="SphericalRectangle"/>, density 1/Ω) from points within <see cref="NearDiagonals"/> of its diagonal, so a
/// point near it gets no more noise from the 1/d² and cos θ_light of its near edge than from its far one. Farther away
/// those vary little over it and sampling by area (density d²/(area·cos θ_light)) costs less for the same noise; a
/// parallelogram is always sampled by area.
/// </summary>
internal sealed class EmissiveRectangle : ILight
{
  /// <summary>Below this solid angle the rectangle is sampled by area: Ω comes from a difference of angles near 2π.</summary>
  const double SmallestSolidAngle = 1e-5;

  /// <summary>Points closer to the centre than this many diagonals are sampled by solid angle.</summary>
  public const double NearDiagonals = 1.0;

  readonly Vector3d centre;
  readonly double nearSquared;

  readonly Vector3d corner, edge1, edge2, normal;
  readonly Rgb radiance;
  readonly double area;
  readonly bool rectangle;

  public EmissiveRectangle(in Vector3d corner, in Vector3d edge1, in Vector3d edge2, in Vector3d normal, in Rgb radiance)
  {
    this.corner = corner;
    this.edge1 = edge1;
    this.edge2 = edge2;
    this.normal = normal;
    this.radiance = radiance;
    area = Vector3d.Cross(edge1, edge2).Length;
    double l1 = edge1.Length, l2 = edge2.Length;
    rectangle = area > 0.0 && Math.Abs(Vector3d.Dot(edge1, edge2)) <= 1e-9 * l1 * l2;
    centre = corner + 0.5 * (edge1 + edge2);
    nearSquared = NearDiagonals * NearDiagonals * (edge1 + edge2).LengthSquared;
  }

  public LightKind Kind => LightKind.Area;

  /// <summary>Flux of a one-sided Lambertian emitter: π·area·mean radiance.</summary>
  public double Power => Math.PI * area * radiance.Average;

  public bool SampleLi(in LightContext ctx, double u, double v, out LightSample sample)
  {
    sample = default;
    // The emitting side faces the point, or nothing of it does (it is planar).
    if (Vector3d.Dot(normal, ctx.P - corner) <= 0.0)
      return false;
    Vector3d toLight;
    double pdf = 0.0;
    SphericalRectangle sr = ByAngle(ctx.P) ? new SphericalRectangle(ctx.P, corner, edge1, edge2) : default;
    if (sr.SolidAngle > SmallestSolidAngle)
    {
      toLight = sr.Sample(u, v);
      pdf = 1.0 / sr.SolidAngle;
    }
    else
      toLight = corner + u * edge1 + v * edge2 - ctx.P;
    double dist2 = toLight.LengthSquared;
    double dist = Math.Sqrt(dist2);
    if (dist <= 1e-9)
      return false;
    Vector3d wi = toLight / dist;
    double cosL = -Vector3d.Dot(normal, wi);
    if (cosL <= 0.0)
      return false;
    if (pdf == 0.0)
      pdf = dist2 / (area * cosL);
    sample = new LightSample(radiance, wi, toLight, dist, pdf);
    return true;
  }

  public double PdfLi(in LightContext ctx, in Vector3d wi, in Vector3d point, in Vector3d n)
  {
    double cosL = -Vector3d.Dot(n, wi);
    if (cosL <= 0.0)
      return 0.0;
    double omega = ByAngle(ctx.P) ? new SphericalRectangle(ctx.P, corner, edge1, edge2).SolidAngle : 0.0;
    if (omega > SmallestSolidAngle)
      return 1.0 / omega;
    return (point - ctx.P).LengthSquared / (area * cosL);
  }

  /// <summary>True when a point at <paramref name="p"/> samples the rectangle by solid angle.</summary>
  bool ByAngle(in Vector3d p) => rectangle && (p - centre).LengthSquared < nearSquared;

  public Rgb Le(in Vector3d n, in Vector3d direction) => Vector3d.Dot(n, direction) < 0.0 ? radiance : Rgb.Zero;
}
