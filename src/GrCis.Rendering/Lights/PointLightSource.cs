using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>A point light without attenuation; lights only surfaces facing it.</summary>
[Serializable]
public class PointLightSource : ILightSource
{
  public double[] intensity;

  public Vector3d? position { get; set; }

  public PointLightSource(Vector3d pos, double intens)
  {
    position = pos;
    intensity = new[] { intens, intens, intens };
  }

  public PointLightSource(Vector3d pos, double[] intens)
  {
    ArgumentNullException.ThrowIfNull(intens);
    position = pos;
    intensity = (double[])intens.Clone();
  }

  /// <summary>
  /// <see cref="intensity"/> attenuated by 1 / (d0 + d1·r + d2·r²) at distance <paramref name="distance"/>, the
  /// <c>Dim</c> of GrCis's area lights; <paramref name="dim"/> null (or short) = no attenuation. The result is this
  /// light's buffer in the worker's context (no array per shadow ray), valid until this light's next call there.
  /// </summary>
  private protected double[] Attenuated(double[]? dim, double distance)
  {
    if (dim == null || dim.Length < 3)
      return intensity;
    double factor = 1.0 / (dim[0] + distance * (dim[1] + distance * dim[2]));
    double[] result = Execution.WorkerContext.Current.LightBuffer(this, intensity.Length);
    for (int i = 0; i < result.Length; i++)
      result[i] = intensity[i] * factor;
    return result;
  }

  public virtual double[]? GetIntensity(Intersection intersection, out Vector3d dir) => Intensity(intersection, out dir);

  /// <summary><see cref="GetIntensity"/> of this class itself (the prepared Whitted kernel calls it directly for exactly this type).</summary>
  internal double[]? Intensity(Intersection intersection, out Vector3d dir)
  {
    dir = (position ?? Vector3d.Zero) - intersection.CoordWorld;
    if (Vector3d.Dot(dir, intersection.Normal) <= 0.0)
      return null;
    return intensity;
  }
}
