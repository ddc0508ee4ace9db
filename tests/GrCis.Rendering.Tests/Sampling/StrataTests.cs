using System;
using System.Linq;
using Rendering;

namespace GrCis.Rendering.Tests.Sampling;

public class StrataTests
{
  [Theory]
  [InlineData(1)]
  [InlineData(2)]
  [InlineData(7)]
  [InlineData(16)]
  [InlineData(100)]
  [InlineData(1000)]
  public void Permute_is_a_permutation_of_the_range(int length)
  {
    foreach (uint pattern in new uint[] { 0u, 1u, 0xDEADBEEFu })
    {
      uint[] image = Enumerable.Range(0, length).Select(i => Strata.Permute((uint)i, (uint)length, pattern)).ToArray();
      Assert.Equal(Enumerable.Range(0, length).Select(i => (uint)i), image.OrderBy(v => v));
    }
  }

  [Theory]
  [InlineData(16, 4, 4)]
  [InlineData(12, 3, 4)]
  [InlineData(7, 1, 7)]
  public void The_samples_of_a_pixel_fill_every_stratum_once_in_2D_and_in_each_axis(int total, int m, int n)
  {
    for (uint pattern = 0; pattern < 50; pattern++)
    {
      var cells = new bool[m, n];
      var columns = new bool[total];
      var rows = new bool[total];
      for (int rank = 0; rank < total; rank++)
      {
        Strata.Sample2D(rank, total, pattern * 7919u, out double u, out double v);
        Assert.InRange(u, 0.0, 1.0 - 1e-15);
        Assert.InRange(v, 0.0, 1.0 - 1e-15);
        int cx = (int)(u * m), cy = (int)(v * n);
        Assert.False(cells[cx, cy], $"pattern {pattern}: two samples in cell ({cx}, {cy})");
        cells[cx, cy] = true;
        Assert.False(columns[(int)(u * total)], "two samples in one column of width 1/total");
        Assert.False(rows[(int)(v * total)], "two samples in one row of height 1/total");
        columns[(int)(u * total)] = rows[(int)(v * total)] = true;
      }
    }
  }

  [Fact]
  public void One_rank_is_uniform_over_the_square_across_pixels()
  {
    // Rank 3 of 16 over many patterns (pixels): a 4x4 histogram stays within 10 % of flat.
    var histogram = new int[4, 4];
    const int patterns = 32000;
    for (uint p = 0; p < patterns; p++)
    {
      Strata.Sample2D(3, 16, p * 2654435761u, out double u, out double v);
      histogram[(int)(u * 4), (int)(v * 4)]++;
    }
    foreach (int count in histogram)
      Assert.InRange(count, patterns / 16 * 0.9, patterns / 16 * 1.1);
  }

  [Fact]
  public void Samples_depend_on_pixel_seed_and_dimension_but_not_on_the_order_they_are_taken()
  {
    static (double, double) At(int x, int y, long seed, uint dimension, int rank)
    {
      MT.seed = seed;
      MT.frame = 0;
      MT.StartPixel(x, y, 16);
      MT.StartSample(rank);
      Strata.Sample2D(dimension, out double u, out double v);
      return (u, v);
    }

    var forward = Enumerable.Range(0, 16).Select(r => At(3, 4, 1, 9, r)).ToArray();
    var backward = Enumerable.Range(0, 16).Reverse().Select(r => At(3, 4, 1, 9, r)).Reverse().ToArray();
    Assert.Equal(forward, backward);
    Assert.NotEqual(forward, Enumerable.Range(0, 16).Select(r => At(4, 4, 1, 9, r)).ToArray());
    Assert.NotEqual(forward, Enumerable.Range(0, 16).Select(r => At(3, 4, 2, 9, r)).ToArray());
    Assert.NotEqual(forward, Enumerable.Range(0, 16).Select(r => At(3, 4, 1, 10, r)).ToArray());
    MT.seed = 0;
  }

  [Fact]
  public void Sample1D_stratifies_the_pixel_samples()
  {
    MT.seed = 5;
    MT.StartPixel(10, 20, 8);
    var bins = new bool[8];
    for (int r = 0; r < 8; r++)
    {
      MT.StartSample(r);
      double x = Strata.Sample1D(77);
      Assert.False(bins[(int)(x * 8)]);
      bins[(int)(x * 8)] = true;
    }
    MT.seed = 0;
  }
}
