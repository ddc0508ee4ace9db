using System;
using Rendering;
using Rendering.Accel;

namespace GrCis.Rendering.Tests.ImageFunctions;

/// <summary>The mirror's largest reflectance band (<c>WhittedKernel.MaxBand</c>) is Math.Max folded from band 0, bit for bit.</summary>
public class MaxBandTests
{
  static double Fold(double[] bands)
  {
    double max = bands[0];
    for (int b = 1; b < bands.Length; b++)
      max = Math.Max(max, bands[b]);
    return max;
  }

  [Fact]
  public void Max_band_equals_the_math_max_fold_with_nans_signed_zeros_and_ties()
  {
    double[] pool = { 0.0, -0.0, 1.0, -1.0, 0.25, 0.25, double.NaN, double.PositiveInfinity, double.NegativeInfinity, double.Epsilon, -double.Epsilon };
    var r = new Random(3);
    for (int n = 0; n < 50000; n++)
    {
      var bands = new double[1 + r.Next(5)];
      for (int b = 0; b < bands.Length; b++)
        bands[b] = r.Next(3) == 0 ? r.NextDouble() - 0.5 : pool[r.Next(pool.Length)];
      if (n % 4 == 0)
        Array.Fill(bands, bands[0]);   // all bands equal, as a Phong reflectance gives them
      Assert.Equal(BitConverter.DoubleToInt64Bits(Fold(bands)), BitConverter.DoubleToInt64Bits(WhittedKernel.MaxBand(bands)));
    }
  }
}
