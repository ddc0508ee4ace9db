using MathSupport;

namespace GrCis.Rendering.Tests.Sampling;

public class RandomJamesTests
{
  [Fact]
  public void Marsaglia_published_check_values_after_20000_numbers()
  {
    var r = new RandomJames(1802, 9373);
    for (int i = 0; i < 20000; i++)
      r.UniformNumber();
    int[] expected = { 6533892, 14220222, 7275067, 6172232, 8354498, 10633180 };
    foreach (int e in expected)
      Assert.Equal(e, (int)(r.UniformNumber() * 4096.0 * 4096.0 + 0.5));
  }

  [Fact]
  public void Validate_reports_success()
  {
    Assert.True(new RandomJames().Validate());
  }

  [Fact]
  public void Uniform_numbers_stay_in_unit_interval_and_have_mean_one_half()
  {
    var r = new RandomJames(12345L);
    double sum = 0;
    for (int i = 0; i < 100000; i++)
    {
      double u = r.UniformNumber();
      Assert.InRange(u, 0.0, 1.0 - 1e-9);
      sum += u;
    }
    Assert.InRange(sum / 100000, 0.49, 0.51);
  }

  [Fact]
  public void Random_integer_covers_both_ends_inclusive()
  {
    var r = new RandomJames(7L);
    bool sawMin = false, sawMax = false;
    for (int i = 0; i < 10000; i++)
    {
      int k = r.RandomInteger(3, 6);
      Assert.InRange(k, 3, 6);
      sawMin |= k == 3;
      sawMax |= k == 6;
    }
    Assert.True(sawMin && sawMax);
  }

  [Fact]
  public void Permutation_yields_each_element_once_then_minus_one()
  {
    var r = new RandomJames(99L);
    RandomJames.Permutation? p = null;
    var seen = new bool[17];
    int k = r.PermutationFirst(17, ref p);
    for (int i = 0; i < 17; i++)
    {
      Assert.InRange(k, 0, 16);
      Assert.False(seen[k]);
      seen[k] = true;
      k = r.PermutationNext(ref p);
    }
    Assert.Equal(-1, k);
  }

  [Fact]
  public void Normal_distribution_has_requested_mean_and_sigma()
  {
    var r = new RandomJames(5L);
    double sum = 0, sum2 = 0;
    const int n = 50000;
    for (int i = 0; i < n; i++)
    {
      double x = r.Normal(2.0, 3.0);
      sum += x;
      sum2 += x * x;
    }
    double mean = sum / n, sigma = System.Math.Sqrt(sum2 / n - mean * mean);
    Assert.InRange(mean, 1.95, 2.05);
    Assert.InRange(sigma, 2.95, 3.05);
  }

  /// <summary>The generator as it was before the lazy table and the branch-free step (the reference numbers).</summary>
  sealed class ReferenceRanmar
  {
    readonly double[] u = new double[97];
    double c = 362436.0 / 16777216.0;
    int i97 = 96, j97 = 32;

    public ReferenceRanmar(ulong seed)
    {
      ulong state = seed;
      for (int k = 0; k < 97; k++)
      {
        ulong z = state += 0x9E3779B97F4A7C15UL;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
        u[k] = ((z ^ (z >> 31)) >> 40) * (1.0 / 16777216.0);
      }
    }

    public double Next()
    {
      double uni = u[i97] - u[j97];
      if (uni < 0.0) uni += 1.0;
      u[i97] = uni;
      if (--i97 < 0) i97 = 96;
      if (--j97 < 0) j97 = 96;
      c -= 7654321.0 / 16777216.0;
      if (c < 0.0) c += 16777213.0 / 16777216.0;
      uni -= c;
      if (uni < 0.0) uni += 1.0;
      return uni;
    }
  }

  [Theory]
  [InlineData(0)]
  [InlineData(1)]
  [InlineData(32)]
  [InlineData(33)]
  [InlineData(34)]
  [InlineData(97)]
  [InlineData(5000)]
  public void Fast_reset_gives_the_eagerly_seeded_sequence_whatever_the_draw_count(int draws)
  {
    // The lazy table switches to the full table after 33 draws: cross that point, stop at it, reseed inside it.
    var r = new RandomJames();
    for (ulong seed = 0; seed < 40; seed++)
    {
      ulong s = seed * 0x9E3779B97F4A7C15UL ^ 12345UL;
      r.ResetFast(s);
      var reference = new ReferenceRanmar(s);
      for (int k = 0; k < draws; k++)
        Assert.Equal(reference.Next(), r.UniformNumber());
    }
    r.ResetFast(7UL);
    var again = new ReferenceRanmar(7UL);
    for (int k = 0; k < 200; k++)
      Assert.Equal(again.Next(), r.UniformNumber());
  }

  [Fact]
  public void Classic_seeds_after_fast_reset_give_marsaglias_check_values()
  {
    var r = new RandomJames();
    r.ResetFast(99UL);
    r.UniformNumber();
    Assert.True(r.Validate());
  }

  [Fact]
  public void Fast_reset_is_reproducible_and_seed_dependent()
  {
    var a = new RandomJames();
    var b = new RandomJames(1L);
    a.ResetFast(42);
    b.ResetFast(42);
    for (int i = 0; i < 200; i++)
      Assert.Equal(a.UniformNumber(), b.UniformNumber());
    a.ResetFast(43);
    b.ResetFast(42);
    Assert.NotEqual(a.UniformNumber(), b.UniformNumber());
  }

  [Fact]
  public void NumericRecipes_is_the_32_bit_linear_congruential_step()
  {
    Assert.Equal(1013904223UL, RandomStatic.numericRecipes(0UL));
    Assert.Equal((1664525UL + 1013904223UL) & 0xFFFFFFFFUL, RandomStatic.numericRecipes(1UL));
  }
}
