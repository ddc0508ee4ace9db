using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>Light that reaches every point from no particular direction.</summary>
[Serializable]
public class AmbientLightSource : ILightSource
{
  /// <summary>Intensity per colour band (usually RGB); the reflectance model weighs it by the surface's ambient coefficient.</summary>
  public double[] intensity;

  /// <summary>Always null: ambient light has no position. Setting it does nothing.</summary>
  public Vector3d? position { get => null; set { } }

  /// <summary>No light until <see cref="intensity"/> is set.</summary>
  public AmbientLightSource() => intensity = new double[3];

  /// <summary>Ambient light of the same intensity in all three bands, e.g. <c>new AmbientLightSource(0.8)</c>.</summary>
  /// <param name="intens">Intensity of each band.</param>
  public AmbientLightSource(double intens) => intensity = new[] { intens, intens, intens };

  /// <summary>Ambient light of the given intensity per band.</summary>
  /// <param name="intens">Intensity per band (copied).</param>
  /// <exception cref="ArgumentNullException"><paramref name="intens"/> is null.</exception>
  public AmbientLightSource(double[] intens)
  {
    ArgumentNullException.ThrowIfNull(intens);
    intensity = (double[])intens.Clone();
  }

  /// <summary>The same <see cref="intensity"/> at every point (this light's own array), with <paramref name="dir"/> zero.</summary>
  /// <param name="intersection">The lit point (not read).</param>
  /// <param name="dir">Zero: ambient light comes from no direction.</param>
  public virtual double[]? GetIntensity(Intersection intersection, out Vector3d dir) => Intensity(out dir);

  /// <summary><see cref="GetIntensity"/> of this class itself (the prepared Whitted kernel calls it directly for exactly this type).</summary>
  internal double[]? Intensity(out Vector3d dir)
  {
    dir = Vector3d.Zero;
    return intensity;
  }
}
