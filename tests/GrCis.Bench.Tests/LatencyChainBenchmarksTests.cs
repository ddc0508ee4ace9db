namespace GrCis.Bench.Tests;

/// <summary>The probe compares like with like: the interleaved rays and the vector lanes compute exactly the sums of one ray after another.</summary>
public class LatencyChainBenchmarksTests
{
  [Fact]
  public void Interleaved_rays_and_vector_lanes_give_the_same_sum_as_one_after_another()
  {
    var probe = new LatencyChainBenchmarks();
    probe.Setup();
    double one = probe.OneByOne();
    Assert.True(double.IsFinite(one) && one != 0.0, $"sum {one}");
    Assert.Equal(one, probe.Pairs());
    Assert.Equal(one, probe.Lanes());
  }
}
