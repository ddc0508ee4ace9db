using System;
using Rendering;

namespace GrCis.Rendering.Tests.Sampling;

public class StrataGridTests
{
  [Theory]
  [InlineData(1)]
  [InlineData(2)]
  [InlineData(3)]
  [InlineData(7)]
  [InlineData(16)]
  [InlineData(36)]
  [InlineData(64)]
  [InlineData(100)]
  [InlineData(256)]
  [InlineData(1000)]
  [InlineData(65536)]
  public void Grid_gives_the_bits_of_Strata_for_every_rank_and_random_patterns(int total)
  {
    var grid = new StrataGrid(total);
    var random = new Random(total);
    for (int trial = 0; trial < 40; trial++)
    {
      uint pattern = (uint)random.NextInt64(0, 1L << 32);
      // Ranks past the ends are clamped by both.
      for (int rank = -2; rank < Math.Min(total, 300) + 2; rank++)
      {
        Strata.Sample2D(rank, total, pattern, out double u, out double v);
        grid.Sample2D(rank, pattern, out double gu, out double gv);
        Assert.Equal(BitConverter.DoubleToInt64Bits(u), BitConverter.DoubleToInt64Bits(gu));
        Assert.Equal(BitConverter.DoubleToInt64Bits(v), BitConverter.DoubleToInt64Bits(gv));
        Assert.Equal(BitConverter.DoubleToInt64Bits(Strata.Sample1D(rank, total, pattern)), BitConverter.DoubleToInt64Bits(grid.Sample1D(rank, pattern)));
      }
    }
  }

  [Fact]
  public void A_count_of_zero_samples_like_one()
  {
    new StrataGrid(0).Sample2D(0, 12345u, out double u, out double v);
    Strata.Sample2D(0, 0, 12345u, out double su, out double sv);
    Assert.Equal((su, sv), (u, v));
  }

  [Fact]
  public void Divisor_divides_exactly_at_the_edges_of_the_32_bit_range()
  {
    uint[] divisors = { 1, 2, 3, 5, 6, 7, 10, 12, 36, 100, 255, 1000, 65535, 65536, 0x7FFFFFFF, 0x80000001, 0xFFFFFFFE, 0xFFFFFFFF };
    var random = new Random(7);
    foreach (uint d in divisors)
    {
      var divisor = new StrataGrid.Divisor(d);
      uint[] edges = { 0, 1, d - 1, d, d + 1, 2 * d - 1, 0x7FFFFFFF, 0x80000000, 0xFFFFFFFE, 0xFFFFFFFF };
      foreach (uint a in edges)
        AssertDivides(divisor, a);
      for (int k = 0; k < 2000; k++)
        AssertDivides(divisor, (uint)random.NextInt64(0, 1L << 32));
    }
  }

  static void AssertDivides(StrataGrid.Divisor divisor, uint a)
  {
    Assert.Equal(a / divisor.Value, divisor.Div(a));
    Assert.Equal(a % divisor.Value, divisor.Mod(a));
  }

  [Fact]
  public void The_sampler_follows_a_changed_count()
  {
    var sampler = (CorrelatedMultiJitterSampler)Sampler.Create(SamplerKind.CorrelatedMultiJitter, seed: 5);
    foreach (int count in new[] { 16, 9, 16, 1, 256 })
    {
      sampler.StartPixel(3, 4, count);
      sampler.StartPixelSample(3, 4, count - 1);
      sampler.Get2D(SampleDimension.PathDirection, 2, out double u, out double v);
      Strata.Sample2D(count - 1, count, sampler.Pattern(SampleDimension.PathDirection, 2), out double su, out double sv);
      Assert.Equal((su, sv), (u, v));
      Assert.Equal(Strata.Sample1D(count - 1, count, sampler.Pattern(SampleDimension.PathRoulette, 1)), sampler.Get1D(SampleDimension.PathRoulette, 1));
    }
  }

  [Fact]
  public void The_sampler_kept_patterns_are_those_of_the_pixel_seed_and_frame_it_is_at()
  {
    var sampler = (CorrelatedMultiJitterSampler)Sampler.Create(SamplerKind.CorrelatedMultiJitter);
    var random = new Random(11);
    // Pixels, seeds and frames change between and within the same few (dimension, instance) pairs, instances past the kept ones too.
    for (int k = 0; k < 3000; k++)
    {
      switch (random.Next(6))
      {
        case 0: sampler.Seed = random.Next(3); break;
        case 1: sampler.Frame = random.Next(3); break;
        case 2: sampler.StartPixel(random.Next(3), random.Next(3), 16); break;
        default: break;
      }
      var dimension = (SampleDimension)random.Next(12);
      int instance = random.Next(4) == 0 ? random.Next(60, 200) : random.Next(4);
      uint expected = Strata.Pattern(sampler.Seed, sampler.Frame, sampler.X, sampler.Y, Strata.Dimension(dimension, instance));
      Assert.Equal(expected, sampler.Pattern(dimension, instance));
    }
  }

  [Fact]
  public void The_sampler_gives_the_bits_of_Strata_while_pixels_counts_seeds_frames_and_ranks_change()
  {
    var sampler = (CorrelatedMultiJitterSampler)Sampler.Create(SamplerKind.CorrelatedMultiJitter);
    var random = new Random(19);
    int[] counts = { 256, 16, 36, 7, 1024, 4096, 1 };
    sampler.StartPixel(0, 0, 256);
    // Counts of every kind of grid, dimensions and instances in and past the kept patterns.
    for (int k = 0; k < 20000; k++)
    {
      switch (random.Next(40))
      {
        case 0: sampler.Seed = random.Next(2); break;
        case 1: sampler.Frame = random.Next(2); break;
        case 2: sampler.StartPixel(random.Next(2), random.Next(2), counts[random.Next(counts.Length)]); break;
        case 3: sampler.Count = counts[random.Next(counts.Length)]; break;
        default: break;
      }
      sampler.Index = random.Next(sampler.Count + 1);
      var dimension = (SampleDimension)random.Next(12);
      int instance = random.Next(5) == 0 ? random.Next(60, 70) : random.Next(3);
      uint pattern = Strata.Pattern(sampler.Seed, sampler.Frame, sampler.X, sampler.Y, Strata.Dimension(dimension, instance));
      sampler.Get2D(dimension, instance, out double u, out double v);
      Strata.Sample2D(sampler.Index, sampler.Count, pattern, out double su, out double sv);
      Assert.Equal(BitConverter.DoubleToInt64Bits(su), BitConverter.DoubleToInt64Bits(u));
      Assert.Equal(BitConverter.DoubleToInt64Bits(sv), BitConverter.DoubleToInt64Bits(v));
      Assert.Equal(Strata.Sample1D(sampler.Index, sampler.Count, pattern), sampler.Get1D(dimension, instance));
    }
  }
}
