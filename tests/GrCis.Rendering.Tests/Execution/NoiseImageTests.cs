using System;
using System.Linq;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;
using GrCis.Rendering.Tests.ImageFunctions;

namespace GrCis.Rendering.Tests.Execution;

/// <summary>The noise estimate of n×n supersampling: its sample order, its half-image estimator and its accuracy against real errors.</summary>
public class NoiseImageTests
{
  [Theory]
  [InlineData(1)]
  [InlineData(2)]
  [InlineData(3)]
  [InlineData(4)]
  [InlineData(7)]
  public void Samples_cover_every_cell_once_and_each_diagonal_every_row_and_column(int n)
  {
    var cells = Enumerable.Range(0, n * n).Select(s => SupersamplingImageSynthesizer.SampleCell(s, n)).ToArray();
    Assert.Equal(n * n, cells.Select(c => (c.I, c.J)).Distinct().Count());
    Assert.All(cells, c => Assert.InRange(c.I, 0, n - 1));
    for (int d = 0; d < n; d++)
    {
      var diagonal = cells.Skip(d * n).Take(n).ToArray();
      Assert.Equal(n, diagonal.Select(c => c.I).Distinct().Count());
      Assert.Equal(n, diagonal.Select(c => c.J).Distinct().Count());
      Assert.All(diagonal, c => Assert.Equal(d % 2 == 1, c.OddDiagonal));
    }
  }

  [Fact]
  public void Estimator_is_the_variance_of_the_mean_for_two_halves()
  {
    var noise = new NoiseImage(2, 1);
    // 2×2 grid: samples 0, 1 on the even diagonal (values 1, 3), samples 2, 3 on the odd one (values 5, 7).
    noise.Set(0, 0, new[] { 16.0 }, new[] { 12.0 }, 4, 2);
    // Means 2 and 6, two samples each: (6 − 2)²·2·2/4² = 4.
    Assert.Equal(4.0, noise.Variance.Data[0], 6);
    Assert.True(float.IsNaN(noise.Variance.Data[1]), "a pixel never set has no estimate");
    Assert.Equal(2.0, noise.Rmse()!.Value, 6);
    Assert.Equal(2.0, noise.StandardError().Data[0], 6);

    // One diagonal only (the first n samples): no second half, no estimate.
    var early = new NoiseImage(1, 1);
    early.Set(0, 0, new[] { 3.0 }, new[] { 0.0 }, 2, 2);
    Assert.Null(early.Rmse());
  }

  [Fact]
  public void Estimated_error_matches_the_error_against_a_converged_render_and_falls_with_samples()
  {
    const int size = 24;
    FloatImage reference = PathTracingTests.Render(CornellScene.Create(diffuse: true), new PathTracing(), size, 1024, seed: 99);
    double previous = double.MaxValue;
    foreach (int spp in new[] { 16, 64 })
    {
      var context = new RenderContext { Noise = new NoiseImage(size, size) };
      FloatImage image = PathTracingTests.Render(CornellScene.Create(diffuse: true), new PathTracing(), size, spp, context: context);
      double actual = Rmse(image, reference), estimated = context.Noise.Rmse()!.Value;
      // The estimate is of the right size (half-images of stratified samples err on the high side: every decision of a
      // path vertex is stratified over the whole pixel, so each half alone is less even than the two together) ...
      Assert.True(estimated / actual is >= 0.7 and <= 2.2, $"{spp} spp: estimated {estimated}, actual {actual}");
      // ... and falls at least as 1/√spp does: 4× the samples, at most half the error.
      Assert.True(estimated < previous / 2, $"{spp} spp: estimated {estimated}, before {previous}");
      previous = estimated;
    }
  }

  /// <summary>Root-mean-square difference over pixels of the band-averaged squared error (as <see cref="NoiseImage"/> measures).</summary>
  static double Rmse(FloatImage a, FloatImage b)
  {
    double sum = 0.0;
    for (int i = 0; i < a.Data.Length; i++)
      sum += (a.Data[i] - b.Data[i]) * (double)(a.Data[i] - b.Data[i]);
    return Math.Sqrt(sum / a.Data.Length);
  }
}
