using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>A point light without attenuation; lights only surfaces facing it.</summary>
[Serializable]
public class PointLightSource : ILightSource
{
  /// <summary>Intensity per colour band (usually RGB); it does not fall off with distance.</summary>
  public double[] intensity;

  /// <summary>Position of the light in world coordinates.</summary>
  public Vector3d? position { get; set; }

  /// <summary>A point light of the same intensity in all three bands, e.g. <c>new PointLightSource(new Vector3d(-5.0, 4.0, -3.0), 1.2)</c>.</summary>
  /// <param name="pos">Position of the light in world coordinates.</param>
  /// <param name="intens">Intensity of each band.</param>
  public PointLightSource(Vector3d pos, double intens)
  {
    position = pos;
    intensity = new[] { intens, intens, intens };
  }

  /// <summary>A point light of the given intensity per band.</summary>
  /// <param name="pos">Position of the light in world coordinates.</param>
  /// <param name="intens">Intensity per band (copied).</param>
  /// <exception cref="ArgumentNullException"><paramref name="intens"/> is null.</exception>
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
    double[] result = Execution.WorkerContext.Current.Get(buffers).For(this, intensity.Length);
    for (int i = 0; i < result.Length; i++)
      result[i] = intensity[i] * factor;
    return result;
  }

  /// <summary>
  /// <see cref="intensity"/> (this light's own array, not attenuated) when the surface at the hit faces the light;
  /// null when it faces away (<c>dir · Normal ≤ 0</c>). Shadows are the image function's business.
  /// </summary>
  /// <param name="intersection">The completed hit to light (its world point and normal are read).</param>
  /// <param name="dir">From the hit point to the light, not normalised (its length is the distance).</param>
  public virtual double[]? GetIntensity(Intersection intersection, out Vector3d dir) => Intensity(intersection, out dir);

  /// <summary><see cref="GetIntensity"/> of this class itself (the prepared Whitted kernel calls it directly for exactly this type).</summary>
  internal double[]? Intensity(Intersection intersection, out Vector3d dir) => Intensity(intersection.CoordWorld, intersection.Normal, out dir);

  /// <summary><see cref="GetIntensity"/> of this class at world point <paramref name="point"/> with unit normal <paramref name="normal"/>.</summary>
  internal double[]? Intensity(in Vector3d point, in Vector3d normal, out Vector3d dir)
  {
    dir = (position ?? Vector3d.Zero) - point;
    if (Vector3d.Dot(dir, normal) <= 0.0)
      return null;
    return intensity;
  }

  /// <summary>The worker's result buffers of attenuated lights (<see cref="Attenuated"/>).</summary>
  static readonly Execution.WorkerSlot<AttenuationBuffers> buffers = new(() => new AttenuationBuffers());

  /// <summary>A worker's result buffers of attenuated lights, one per light: few lights, a linear search.</summary>
  sealed class AttenuationBuffers
  {
    object?[] owners = new object?[4];
    double[]?[] values = new double[]?[4];

    /// <summary>The buffer of <paramref name="bands"/> values for light <paramref name="owner"/>.</summary>
    public double[] For(object owner, int bands)
    {
      int i = 0;
      for (; i < owners.Length && owners[i] != null; i++)
        if (ReferenceEquals(owners[i], owner))
        {
          double[] b = values[i]!;
          return b.Length == bands ? b : values[i] = new double[bands];
        }
      if (i == owners.Length && i >= 64)
      {
        // A long-lived thread meets new lights with every scene: forget the old ones (their buffers stay valid for their callers).
        System.Array.Clear(owners);
        System.Array.Clear(values);
        i = 0;
      }
      else if (i == owners.Length)
      {
        System.Array.Resize(ref owners, 2 * i);
        System.Array.Resize(ref values, 2 * i);
      }
      owners[i] = owner;
      return values[i] = new double[bands];
    }
  }
}
