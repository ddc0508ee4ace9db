using System;
using Rendering.Execution;

namespace Rendering;

/// <summary>
/// What the Monte Carlo image functions (<see cref="PathTracing"/>, <see cref="Distributed.DistributedRayTracing"/>) share
/// on top of Whitted's <see cref="RayTracing"/>: every random decision of a vertex comes from the worker's
/// <see cref="Sampler"/> in a <see cref="SampleDimension"/> of its own, instanced by the vertex's depth;
/// <see cref="RayTracing.MaxLevel"/> is the deepest vertex; Russian roulette ends a path by its throughput; and each
/// says whether it follows the --no-reflections/--no-refractions switches, so a front end can tell the user when it does not.
/// </summary>
[Serializable]
public abstract class MonteCarloRayTracing : RayTracing
{
  /// <summary>A Monte Carlo image function of <paramref name="sc"/>.</summary>
  /// <param name="sc">The scene, or null to render the current scene (<see cref="MT.scene"/>).</param>
  protected MonteCarloRayTracing(IRayScene? sc = null) : base(sc)
  {
  }

  /// <summary>
  /// True when <see cref="RayTracing.DoReflections"/> and <see cref="RayTracing.DoRefractions"/> decide which rays are
  /// traced; false when scattering follows the materials whatever they say (a front end then notes the switches as ignored).
  /// </summary>
  public virtual bool FollowsRayTypeSwitches => true;

  /// <summary>The worker's sampler: the source of every random decision of a vertex.</summary>
  private protected static Sampler VertexSampler => WorkerContext.Current.Sampler;

  /// <summary>
  /// Russian roulette at <paramref name="vertex"/>: survival min(1, √max <paramref name="throughput"/>) (as Cycles),
  /// decided by <see cref="SampleDimension.PathRoulette"/>; a survivor's throughput is divided by it. False ends the path.
  /// </summary>
  private protected static bool Roulette(Sampler sampler, int vertex, ref Rgb throughput)
  {
    double survive = Math.Sqrt(throughput.Max);
    if (survive >= 1.0)
      return true;   // sure to survive: no value needed (asking would not change the other dimensions' values)
    if (sampler.Get1D(SampleDimension.PathRoulette, vertex) >= survive)
      return false;
    throughput *= 1.0 / survive;
    return true;
  }
}
