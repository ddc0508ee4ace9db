using System;
using MathSupport;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// A parallelogram area light (corner <see cref="PointLightSource.position"/>, edges
/// <see cref="width"/> and <see cref="height"/>). Each sample of a pixel picks a point of the light,
/// stratified by the pixel's sample rank (<see cref="MT.rank"/> of <see cref="MT.total"/>): one per stratum of
/// the light in 2D and in each edge's direction (<see cref="Strata"/>), a pure function of the pixel, the rank and
/// the light, so the samples of a pixel may be taken in any order or in several passes. With one sample per pixel
/// the point is uniform from <see cref="MT.rnd"/>, as in GrCis.
/// </summary>
[Serializable]
public class RectangleLightSource : PointLightSource
{
  /// <summary>First edge of the parallelogram, a world vector from the corner <see cref="PointLightSource.position"/> (default +x, length 1).</summary>
  public Vector3d width = Vector3d.UnitX;
  /// <summary>Second edge of the parallelogram, a world vector from the corner (default +y, length 1).</summary>
  public Vector3d height = Vector3d.UnitY;

  /// <summary>Attenuation 1 / (d0 + d1·r + d2·r²); null = none.</summary>
  public double[]? Dim = { 0.5, 1.0, 0.1 };

  /// <summary>A parallelogram light of the same intensity in all three bands, with the default attenuation <see cref="Dim"/>.</summary>
  /// <param name="pos">One corner in world coordinates.</param>
  /// <param name="wid">First edge from that corner (<see cref="width"/>).</param>
  /// <param name="hei">Second edge from that corner (<see cref="height"/>).</param>
  /// <param name="intens">Intensity of each band, before attenuation.</param>
  public RectangleLightSource(Vector3d pos, Vector3d wid, Vector3d hei, double intens) : base(pos, intens)
  {
    width = wid;
    height = hei;
  }

  /// <summary>A parallelogram light of the given intensity per band, with the default attenuation <see cref="Dim"/>.</summary>
  /// <param name="pos">One corner in world coordinates.</param>
  /// <param name="wid">First edge from that corner (<see cref="width"/>).</param>
  /// <param name="hei">Second edge from that corner (<see cref="height"/>).</param>
  /// <param name="intens">Intensity per band before attenuation (copied).</param>
  public RectangleLightSource(Vector3d pos, Vector3d wid, Vector3d hei, double[] intens) : base(pos, intens)
  {
    width = wid;
    height = hei;
  }

  /// <summary>Position of the light point used by the current sample, as (u, v) in [0,1)².</summary>
  void SampleUV(out double u, out double v)
  {
    Execution.WorkerContext context = Execution.WorkerContext.Current;
    if (context.Sampler.Count <= 1)
    {
      RandomJames rnd = context.Rnd ??= new RandomJames();
      u = rnd.UniformNumber();
      v = rnd.UniformNumber();
      return;
    }
    context.Sampler.Get2D(SampleDimension.RectangleLight, Instance(), out u, out v);
  }

  /// <summary>This light's instance of <see cref="SampleDimension.RectangleLight"/>: from its corner and edges, the same in every clone and run.</summary>
  int Instance()
  {
    long h = Mix(Mix(Mix(17, position ?? Vector3d.Zero), width), height);
    return (int)(h ^ (h >> 32));
  }

  static long Mix(long h, in Vector3d v) =>
    ((h * 31 ^ BitConverter.DoubleToInt64Bits(v.X)) * 31 ^ BitConverter.DoubleToInt64Bits(v.Y)) * 31 ^ BitConverter.DoubleToInt64Bits(v.Z);

  /// <summary>
  /// Light from one point of the parallelogram, chosen for the current sample: the intensity attenuated by
  /// <see cref="Dim"/> at that point's distance, or null when the surface faces away from that point. The array
  /// returned may be a buffer of the current worker, valid until this light's next call there.
  /// </summary>
  /// <param name="intersection">The completed hit to light (its world point and normal are read).</param>
  /// <param name="dir">From the hit point to the chosen light point, not normalised.</param>
  public override double[]? GetIntensity(Intersection intersection, out Vector3d dir)
  {
    SampleUV(out double u, out double v);
    Vector3d sample = (position ?? Vector3d.Zero) + u * width + v * height;
    dir = sample - intersection.CoordWorld;
    if (Vector3d.Dot(dir, intersection.Normal) <= 0.0)
      return null;
    return Attenuated(Dim, dir.Length);
  }
}
