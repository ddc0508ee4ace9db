using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>Light that reaches every point from no particular direction.</summary>
[Serializable]
public class AmbientLightSource : ILightSource
{
  public double[] intensity;

  public Vector3d? position { get => null; set { } }

  /// <summary>No light until <see cref="intensity"/> is set.</summary>
  public AmbientLightSource() => intensity = new double[3];

  public AmbientLightSource(double intens) => intensity = new[] { intens, intens, intens };

  public AmbientLightSource(double[] intens)
  {
    ArgumentNullException.ThrowIfNull(intens);
    intensity = (double[])intens.Clone();
  }

  public virtual double[]? GetIntensity(Intersection intersection, out Vector3d dir) => Intensity(out dir);

  /// <summary><see cref="GetIntensity"/> of this class itself (the prepared Whitted kernel calls it directly for exactly this type).</summary>
  internal double[]? Intensity(out Vector3d dir)
  {
    dir = Vector3d.Zero;
    return intensity;
  }
}
