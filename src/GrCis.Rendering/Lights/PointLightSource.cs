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

  public virtual double[]? GetIntensity(Intersection intersection, out Vector3d dir)
  {
    dir = (position ?? Vector3d.Zero) - intersection.CoordWorld;
    if (Vector3d.Dot(dir, intersection.Normal) <= 0.0)
      return null;
    return intensity;
  }
}
