using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// Any other <see cref="ILightSource"/> (a student's own, a subclass of a GrCis light) in the light model: a delta
/// light asked through its <see cref="ILightSource.GetIntensity"/>, as Whitted ray tracing asks it, its intensity I
/// counted as π·I (see <see cref="GrCisLight"/>). Zero direction (ambient light) gives no sample. The light reads the
/// hit's normal to tell the lit side: when the vertex gathers light on the inner side, it is given a copy of the hit
/// with the facing normal (the hit itself is never changed).
/// </summary>
internal sealed class CustomLight : ILight
{
  readonly ILightSource source;
  readonly Intersection view = new();

  public CustomLight(ILightSource source) => this.source = source;

  public LightKind Kind => LightKind.DeltaPosition;

  /// <summary>π·I for a subclass of <see cref="PointLightSource"/>, else π (nothing is known before it is asked).</summary>
  public double Power => source is PointLightSource { intensity: double[] i } ? Math.PI * Rgb.From(i).Average : Math.PI;

  public bool SampleLi(in LightContext ctx, double u, double v, out LightSample sample)
  {
    sample = default;
    Intersection? hit = ctx.Hit;
    if (hit == null)
      return false;
    if (Vector3d.Dot(hit.Normal, ctx.N) <= 0.0)
      hit = Facing(hit, ctx.N);
    double[]? intensity = source.GetIntensity(hit, out Vector3d dir);
    double dist = dir.Length;
    if (intensity == null || !(dist > 0.0))
      return false;
    sample = new LightSample(Rgb.From(intensity) * Math.PI, dir / dist, dir, dist, 1.0);
    return true;
  }

  /// <summary>The hit as seen from its other side: a copy (kept for the next call) whose normal is <paramref name="n"/>.</summary>
  Intersection Facing(Intersection hit, in Vector3d n)
  {
    Intersection c = view;
    c.Enter = hit.Enter;
    c.Front = hit.Front;
    c.T = hit.T;
    c.Solid = hit.Solid;
    c.SolidData = hit.SolidData;
    c.CoordLocal = hit.CoordLocal;
    c.NormalLocal = hit.NormalLocal;
    c.CoordWorld = hit.CoordWorld;
    c.CoordObject = hit.CoordObject;
    c.TextureCoord = hit.TextureCoord;
    c.Normal = n;
    c.TangentU = hit.TangentU;
    c.TangentV = hit.TangentV;
    c.LocalToWorld = hit.LocalToWorld;
    c.WorldToLocal = hit.WorldToLocal;
    c.LocalToObject = hit.LocalToObject;
    c.SurfaceColor = hit.SurfaceColor;
    c.ReflectanceModel = hit.ReflectanceModel;
    c.Material = hit.Material;
    c.Textures = hit.Textures;
    c.completed = hit.completed;
    c.textureApplied = hit.textureApplied;
    return c;
  }

  public double PdfLi(in LightContext ctx, in Vector3d wi, in Vector3d point, in Vector3d normal) => 0.0;

  public Rgb Le(in Vector3d normal, in Vector3d direction) => Rgb.Zero;
}
