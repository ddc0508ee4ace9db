using System;
using Rendering.Accel;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>The culls' bound on 1/|d| (<see cref="CullBounds.UpperInverseLength"/>) is never below the exact quotient and close above it.</summary>
public class CullBoundsTests
{
  [Fact]
  public void Upper_inverse_length_is_at_least_the_exact_quotient_and_within_three_percent()
  {
    var r = new Random(12);
    for (int n = 0; n < 200000; n++)
    {
      // |d|² from 10^-300 to 10^300: the estimate's range and both exact ends.
      double x = Math.Pow(10.0, 600.0 * r.NextDouble() - 300.0) * (1.0 + r.NextDouble());
      double exact = 1.0 / Math.Sqrt(x);
      double upper = CullBounds.UpperInverseLength(x);
      Assert.True(upper >= exact, $"x = {x:R}: {upper:R} < {exact:R}");
      Assert.True(upper <= 1.03 * exact, $"x = {x:R}: {upper:R} more than 3 % above {exact:R}");
    }
    Assert.Equal(double.PositiveInfinity, CullBounds.UpperInverseLength(0.0));
    Assert.True(double.IsNaN(CullBounds.UpperInverseLength(double.NaN)));
  }
}
