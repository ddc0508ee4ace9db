using System;
using Rendering;

namespace GrCis.Rendering.Tests.Sampling;

public class FastDivisorTests
{
  [Fact]
  public void Quotient_and_remainder_equal_the_hardware_division_for_every_kind_of_dividend()
  {
    var r = new Random(9);
    uint[] divisors = { 1, 2, 3, 5, 7, 10, 16, 17, 255, 256, 1000, 65535, 65536, 65537, 1u << 31, (1u << 31) + 1, uint.MaxValue - 1, uint.MaxValue };
    foreach (uint d in divisors)
      Check(d, r);
    for (uint d = 1; d <= 300; d++)
      Check(d, r);
    for (int k = 0; k < 200; k++)
      Check((uint)r.NextInt64(1, 1L << 32), r);
  }

  static void Check(uint d, Random r)
  {
    var f = new FastDivisor(d);
    uint[] edges = { 0, 1, d - 1, d, d + 1, 2 * d - 1, 2 * d, uint.MaxValue, uint.MaxValue - 1, uint.MaxValue - d };
    foreach (uint a in edges)
      Same(f, a);
    for (int k = 0; k < 2000; k++)
      Same(f, (uint)r.NextInt64(0, 1L << 32));
  }

  static void Same(FastDivisor f, uint a)
  {
    Assert.Equal(a / f.Value, f.Divide(a));
    Assert.Equal(a % f.Value, f.Remainder(a));
  }

  [Fact]
  public void A_zero_divisor_is_refused() => Assert.Throws<ArgumentOutOfRangeException>(() => new FastDivisor(0));

  [Fact]
  public void Prepared_grid_gives_the_same_sample_bits_as_the_plain_pattern()
  {
    var r = new Random(4);
    foreach (int total in new[] { 0, 1, 2, 3, 12, 16, 63, 64, 100, 256, 1000, 1024, 4096, 65536 })
    {
      var grid = new StrataGrid(total);
      for (int k = 0; k < 500; k++)
      {
        int rank = r.Next(-2, Math.Max(total, 1) + 2);
        uint pattern = (uint)r.NextInt64(0, 1L << 32);
        Strata.Sample2D(rank, total, pattern, out double u0, out double v0);
        Strata.Sample2D(rank, grid, pattern, out double u1, out double v1);
        Assert.Equal(BitConverter.DoubleToInt64Bits(u0), BitConverter.DoubleToInt64Bits(u1));
        Assert.Equal(BitConverter.DoubleToInt64Bits(v0), BitConverter.DoubleToInt64Bits(v1));
        Assert.Equal(BitConverter.DoubleToInt64Bits(Strata.Sample1D(rank, total, pattern)), BitConverter.DoubleToInt64Bits(Strata.Sample1D(rank, grid, pattern)));
      }
    }
  }
}
