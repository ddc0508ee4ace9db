using System;
using Rendering;

namespace GrCis.Rendering.Tests.Materials;

/// <summary>The lobe probabilities of <see cref="PathBsdf"/>: the shortcut for a lone lobe gives the bits of the divisions.</summary>
public class PathBsdfLobeTests
{
  [Fact]
  public void Lobe_probabilities_are_the_bits_of_each_weight_over_the_sum_for_random_and_edge_weights()
  {
    var random = new Random(3);
    double[] specials = { 0.0, 1e-300, 5e-324, 0.25, 0.73, 1.0, 3.0, 1e300, double.MaxValue, double.PositiveInfinity, double.NaN };
    double Pick() => random.Next(3) switch
    {
      0 => specials[random.Next(specials.Length)],
      1 => 0.0,
      _ => random.NextDouble() * Math.Pow(10.0, random.Next(-5, 5)),
    };
    for (int k = 0; k < 20000; k++)
    {
      double wD = Pick(), wS = Pick(), wT = Pick();
      bool scatters = PathBsdf.LobeProbabilities(wD, wS, wT, out double pD, out double pS, out double pT);
      double total = wD + wS + wT;
      Assert.Equal(total > 0.0, scatters);
      if (!scatters)
        continue;
      Assert.Equal(BitConverter.DoubleToInt64Bits(wD / total), BitConverter.DoubleToInt64Bits(pD));
      Assert.Equal(BitConverter.DoubleToInt64Bits(wS / total), BitConverter.DoubleToInt64Bits(pS));
      Assert.Equal(BitConverter.DoubleToInt64Bits(wT / total), BitConverter.DoubleToInt64Bits(pT));
    }
  }

  [Theory]
  [InlineData(0.5, 0.0, 0.0, 1.0, 0.0, 0.0)]
  [InlineData(0.0, 0.9, 0.0, 0.0, 1.0, 0.0)]
  [InlineData(0.0, 0.0, 1.0, 0.0, 0.0, 1.0)]
  [InlineData(0.25, 0.5, 0.25, 0.25, 0.5, 0.25)]
  public void A_lone_lobe_is_chosen_always(double wD, double wS, double wT, double eD, double eS, double eT)
  {
    Assert.True(PathBsdf.LobeProbabilities(wD, wS, wT, out double pD, out double pS, out double pT));
    Assert.Equal((eD, eS, eT), (pD, pS, pT));
  }

  [Fact]
  public void A_black_surface_scatters_nothing()
  {
    Assert.False(PathBsdf.LobeProbabilities(0.0, 0.0, 0.0, out double pD, out double pS, out double pT));
    Assert.Equal((0.0, 0.0, 0.0), (pD, pS, pT));
  }
}
