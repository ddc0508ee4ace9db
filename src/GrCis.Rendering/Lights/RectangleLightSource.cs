using System;
using MathSupport;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// A parallelogram area light (corner <see cref="PointLightSource.position"/>, edges
/// <see cref="width"/> and <see cref="height"/>). Each sample of a pixel picks a point of the light,
/// stratified by the pixel's sample rank (<see cref="MT.rank"/> of <see cref="MT.total"/>) through
/// two independent random permutations of the strata.
/// </summary>
[Serializable]
public class RectangleLightSource : PointLightSource
{
  public Vector3d width = Vector3d.UnitX;
  public Vector3d height = Vector3d.UnitY;

  /// <summary>Attenuation 1 / (d0 + d1·r + d2·r²); null = none.</summary>
  public double[]? Dim = { 0.5, 1.0, 0.1 };

  // Stratification state per light and thread: the strata belong to the pixel being sampled.
  [NonSerialized] System.Threading.ThreadLocal<SamplingState>? states;

  sealed class SamplingState
  {
    public int total = -1, rank = -1, pixelX = -1, pixelY = -1;
    public RandomJames.Permutation? permU, permV;
    public double u, v;
  }

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
    RandomJames rnd = MT.rnd;
    int total = MT.total;
    if (total <= 1)
    {
      u = rnd.UniformNumber();
      v = rnd.UniformNumber();
      return;
    }

    // Created once for all threads: two threads racing to create it would lose one's strata half-way through a pixel.
    SamplingState s = System.Threading.LazyInitializer.EnsureInitialized(ref states, () => new System.Threading.ThreadLocal<SamplingState>(() => new SamplingState())).Value!;
    bool samePixel = s.pixelX == MT.x && s.pixelY == MT.y && s.total == total;
    if (samePixel && s.rank == MT.rank)
    {
      u = s.u;
      v = s.v;
      return;
    }

    int uCell, vCell;
    if (!samePixel || MT.rank < s.rank)
    {
      s.pixelX = MT.x;
      s.pixelY = MT.y;
      s.total = total;
      uCell = rnd.PermutationFirst(total, ref s.permU);
      vCell = rnd.PermutationFirst(total, ref s.permV);
    }
    else
    {
      uCell = Math.Max(rnd.PermutationNext(ref s.permU), 0);
      vCell = Math.Max(rnd.PermutationNext(ref s.permV), 0);
    }
    s.rank = MT.rank;
    s.u = u = (uCell + rnd.UniformNumber()) / total;
    s.v = v = (vCell + rnd.UniformNumber()) / total;
  }

  public override double[]? GetIntensity(Intersection intersection, out Vector3d dir)
  {
    SampleUV(out double u, out double v);
    Vector3d sample = (position ?? Vector3d.Zero) + u * width + v * height;
    dir = sample - intersection.CoordWorld;
    if (Vector3d.Dot(dir, intersection.Normal) <= 0.0)
      return null;
    if (Dim == null || Dim.Length < 3)
      return intensity;

    double dist = dir.Length;
    double factor = 1.0 / (Dim[0] + dist * (Dim[1] + dist * Dim[2]));
    double[] result = new double[intensity.Length];
    for (int i = 0; i < result.Length; i++)
      result[i] = intensity[i] * factor;
    return result;
  }
}
