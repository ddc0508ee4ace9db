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
  public Vector3d width = Vector3d.UnitX;
  public Vector3d height = Vector3d.UnitY;

  /// <summary>Attenuation 1 / (d0 + d1·r + d2·r²); null = none.</summary>
  public double[]? Dim = { 0.5, 1.0, 0.1 };

  public RectangleLightSource(Vector3d pos, Vector3d wid, Vector3d hei, double intens) : base(pos, intens)
  {
    width = wid;
    height = hei;
  }

  public RectangleLightSource(Vector3d pos, Vector3d wid, Vector3d hei, double[] intens) : base(pos, intens)
  {
    width = wid;
    height = hei;
  }

  /// <summary>Position of the light point used by the current sample, as (u, v) in [0,1)².</summary>
  void SampleUV(out double u, out double v)
  {
    if (MT.total <= 1)
    {
      RandomJames rnd = MT.rnd;
      u = rnd.UniformNumber();
      v = rnd.UniformNumber();
      return;
    }
    Execution.WorkerContext.Current.Sampler.Get2D(SampleDimension.RectangleLight, Instance(), out u, out v);
  }

  /// <summary>This light's instance of <see cref="SampleDimension.RectangleLight"/>: from its corner and edges, the same in every clone and run.</summary>
  int Instance()
  {
    long h = Mix(Mix(Mix(17, position ?? Vector3d.Zero), width), height);
    return (int)(h ^ (h >> 32));
  }

  static long Mix(long h, in Vector3d v) =>
    ((h * 31 ^ BitConverter.DoubleToInt64Bits(v.X)) * 31 ^ BitConverter.DoubleToInt64Bits(v.Y)) * 31 ^ BitConverter.DoubleToInt64Bits(v.Z);

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
