using Utilities;

namespace GrCis.Rendering.Tests.Utilities;

public class ETFTests
{
  [Fact]
  public void A_steady_computation_is_estimated_exactly()
  {
    // 10 s per tenth: the whole takes 100 s, whatever the weights.
    var etf = new ETF();
    for (int k = 1; k < 10; k++)
    {
      float total = etf.Estimate(10.0f * k, 0.1f * k, out float left);
      Assert.Equal(100.0f, total, 3);
      Assert.Equal(100.0f - 10.0f * k, left, 3);
    }
  }

  [Fact]
  public void A_slow_down_shows_in_the_local_part_first()
  {
    // Half done in 10 s, then the next tenths take 10 s each: the global rate alone says 20 s in all.
    var global = new ETF(global: 1.0f);
    var local = new ETF(global: 0.0f, intermediateSteps: 0);
    global.Estimate(10.0f, 0.5f, out _);
    local.Estimate(10.0f, 0.5f, out _);
    float g = global.Estimate(20.0f, 0.6f, out _);
    float l = local.Estimate(20.0f, 0.6f, out float left);
    Assert.Equal(20.0f / 0.6f, g, 3);
    Assert.Equal(0.5f * (20.0f + 100.0f), l, 3);   // smoothed: half the old estimate, half the last step's rate
    Assert.Equal(0.4f * l, left, 3);
  }

  [Fact]
  public void Nothing_or_everything_finished_gives_no_estimate()
  {
    var etf = new ETF();
    Assert.Equal(0.0f, etf.Estimate(5.0f, 0.0f, out float a));
    Assert.Equal(0.0f, a);
    Assert.Equal(0.0f, etf.Estimate(5.0f, 1.0f, out float b));
    Assert.Equal(0.0f, b);
  }
}
