using Rendering;
using Rendering.Distributed;

namespace GrCis.Rendering.Tests.ImageFunctions;

/// <summary>The Monte Carlo base: which functions follow the ray-type switches, and Russian roulette's survival rule.</summary>
public class MonteCarloRayTracingTests
{
  [Fact]
  public void Distributed_ray_tracing_follows_the_ray_type_switches_and_path_tracing_does_not()
  {
    Assert.True(new DistributedRayTracing().FollowsRayTypeSwitches);
    Assert.False(new PathTracing().FollowsRayTypeSwitches);
  }

  [Fact]
  public void Roulette_keeps_bright_paths_and_divides_a_survivors_throughput_by_its_survival()
  {
    var sampler = new IndependentSampler();
    sampler.StartPixel(0, 0, 1);
    var bright = new Rgb(0.5, 2.0, 1.0);
    Assert.True(Roulette(sampler, 3, ref bright));
    Assert.Equal(2.0, bright.G);   // survival 1: unchanged

    // Throughput 0.25: survival √0.25 = 0.5; over many vertices about half survive, each scaled by 2.
    int survived = 0;
    for (int vertex = 0; vertex < 4000; vertex++)
    {
      var dim = new Rgb(0.25);
      if (Roulette(sampler, vertex, ref dim))
      {
        survived++;
        Assert.Equal(0.5, dim.R, 12);
      }
    }
    Assert.InRange(survived / 4000.0, 0.46, 0.54);
  }

  static bool Roulette(Sampler sampler, int vertex, ref Rgb throughput) => Probe.Roulette(sampler, vertex, ref throughput);

  /// <summary>Reaches the base's helper as a subclass would.</summary>
  sealed class Probe : MonteCarloRayTracing
  {
    public static new bool Roulette(Sampler sampler, int vertex, ref Rgb throughput) => MonteCarloRayTracing.Roulette(sampler, vertex, ref throughput);
  }
}
