using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// GrCis's <see cref="PointLightSource"/>, <see cref="RectangleLightSource"/> and <see cref="SphereLightSource"/>
/// (their exact types) in the light model. They have no surface in the scene, so they are delta lights: one point
/// per sample, from the integrator's own (u, v). A light of intensity I lights a Lambertian surface of albedo a as
/// Whitted does, a·I·cos θ: its sample carries π·I (times the <c>Dim</c> attenuation at the point's distance).
/// </summary>
internal sealed class GrCisLight : ILight
{
  enum Shape { Point, Rectangle, Sphere }

  readonly Shape shape;
  readonly Vector3d position, width, height;
  readonly double radius;
  readonly double[]? dim;
  readonly Rgb intensity;

  GrCisLight(Shape shape, PointLightSource source, Vector3d width, Vector3d height, double radius, double[]? dim)
  {
    this.shape = shape;
    position = source.position ?? Vector3d.Zero;
    this.width = width;
    this.height = height;
    this.radius = radius;
    this.dim = dim != null && dim.Length >= 3 ? dim : null;
    intensity = Rgb.From(source.intensity) * Math.PI;
  }

  /// <summary>The adapter for a light of one of GrCis's own types (not a subclass, which may light differently); null otherwise.</summary>
  public static GrCisLight? For(ILightSource source)
  {
    Type type = source.GetType();
    if (type == typeof(PointLightSource))
      return new GrCisLight(Shape.Point, (PointLightSource)source, default, default, 0.0, null);
    if (type == typeof(RectangleLightSource))
    {
      var r = (RectangleLightSource)source;
      return new GrCisLight(Shape.Rectangle, r, r.width, r.height, 0.0, r.Dim);
    }
    if (type == typeof(SphereLightSource))
    {
      var s = (SphereLightSource)source;
      return new GrCisLight(s.radius > 0.0 ? Shape.Sphere : Shape.Point, s, default, default, s.radius, s.Dim);
    }
    return null;
  }

  public LightKind Kind => LightKind.DeltaPosition;

  /// <summary>
  /// Without attenuation the light reaches every facing point with irradiance π·I: the power through a unit area
  /// (the scene's size is not known here); with it, at most π·I/d0.
  /// </summary>
  public double Power => intensity.Average * (dim != null && dim[0] > 0.0 ? 1.0 / dim[0] : 1.0);

  public bool SampleLi(in LightContext ctx, double u, double v, out LightSample sample)
  {
    Vector3d toLight;
    switch (shape)
    {
      case Shape.Rectangle:
        toLight = position + u * width + v * height - ctx.P;
        break;
      case Shape.Sphere:
        toLight = SpherePoint(ctx.P, u, v);
        break;
      default:
        toLight = position - ctx.P;
        break;
    }
    double dist = toLight.Length;
    if (!(dist > 0.0) || Vector3d.Dot(toLight, ctx.N) <= 0.0)
    {
      sample = default;
      return false;
    }
    Rgb l = dim == null ? intensity : intensity * (1.0 / (dim[0] + dist * (dim[1] + dist * dim[2])));
    sample = new LightSample(l, toLight / dist, toLight, dist, 1.0);
    return true;
  }

  /// <summary>As <see cref="SphereLightSource"/>: a direction uniform in the cone the sphere subtends, then its nearer point; the centre from inside.</summary>
  Vector3d SpherePoint(in Vector3d p, double u, double v)
  {
    Vector3d toCentre = position - p;
    double dist2 = toCentre.LengthSquared;
    double r2 = radius * radius;
    if (dist2 <= r2)
      return toCentre;
    double dist = Math.Sqrt(dist2);
    double cosMax = Math.Sqrt(Math.Max(0.0, 1.0 - r2 / dist2));
    Vector3d w = SampleWarp.UniformCone(u, v, toCentre / dist, cosMax);
    double b = Vector3d.Dot(w, toCentre);
    return w * (b - Math.Sqrt(Math.Max(0.0, b * b - dist2 + r2)));
  }

  public double PdfLi(in LightContext ctx, in Vector3d wi, in Vector3d point, in Vector3d normal) => 0.0;

  public Rgb Le(in Vector3d normal, in Vector3d direction) => Rgb.Zero;
}
