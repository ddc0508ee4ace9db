using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// The background (<see cref="IRayScene.Background"/>, else <see cref="IRayScene.BackgroundColor"/>) as an infinite
/// light: sampled cosine-weighted around the shading normal (density cos θ/π), found too by rays that leave the scene.
/// Its power is what the background sends through the disk of the scene's bounding sphere (as pbrt): π·r²·π·mean radiance.
/// </summary>
internal sealed class EnvironmentLight : ILight
{
  readonly IBackground? background;
  readonly Rgb colour;
  readonly double[] buffer;
  readonly double power;

  /// <param name="sceneRadius">Radius of a sphere bounding the scene (<see cref="SceneBounds.Radius"/>).</param>
  public EnvironmentLight(IRayScene scene, int bands, double sceneRadius)
  {
    background = scene.Background;
    colour = scene.BackgroundColor is double[] bg ? Rgb.From(bg) : Rgb.Zero;
    buffer = new double[Math.Max(bands, 3)];
    double r = sceneRadius > 0.0 && double.IsFinite(sceneRadius) ? sceneRadius : 1.0;
    power = Math.PI * r * r * Math.PI * MeanRadiance();
  }

  public LightKind Kind => LightKind.Infinite;

  /// <summary>Flux through the scene's bounding disk, π·r²·π·mean radiance; the mean from 26 fixed directions.</summary>
  public double Power => power;

  public bool SampleLi(in LightContext ctx, double u, double v, out LightSample sample)
  {
    Vector3d wi = SampleWarp.CosineHemisphere(u, v, ctx.N);
    double cos = Vector3d.Dot(wi, ctx.N);
    if (cos <= 0.0)
    {
      sample = default;
      return false;
    }
    sample = new LightSample(Radiance(wi), wi, wi, double.PositiveInfinity, cos / Math.PI);
    return true;
  }

  public double PdfLi(in LightContext ctx, in Vector3d wi, in Vector3d point, in Vector3d normal) =>
    Math.Max(0.0, Vector3d.Dot(wi, ctx.N)) / Math.PI;

  public Rgb Le(in Vector3d normal, in Vector3d direction) => Radiance(direction);

  /// <summary>Radiance of the background seen in <paramref name="direction"/>.</summary>
  public Rgb Radiance(in Vector3d direction)
  {
    if (background == null)
      return colour;
    background.GetColor(direction, buffer);
    return Rgb.From(buffer);
  }

  double MeanRadiance()
  {
    if (background == null)
      return Math.Max(colour.Average, 0.0);
    double sum = 0.0;
    int n = 0;
    for (int x = -1; x <= 1; x++)
      for (int y = -1; y <= 1; y++)
        for (int z = -1; z <= 1; z++)
          if (x != 0 || y != 0 || z != 0)
          {
            sum += Math.Max(Radiance(new Vector3d(x, y, z).Normalized()).Average, 0.0);
            n++;
          }
    return sum / n;
  }
}
