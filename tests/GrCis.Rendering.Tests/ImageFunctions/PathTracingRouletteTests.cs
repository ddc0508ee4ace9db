using System;
using Rendering;

namespace GrCis.Rendering.Tests.ImageFunctions;

/// <summary>Where the path tracer plays Russian roulette.</summary>
public class PathTracingRouletteTests
{
  /// <summary>A sampler that must not be asked (the roulette would draw from it).</summary>
  sealed class Unasked : Sampler
  {
    public override SamplerKind Kind => SamplerKind.Independent;
    public override double Get1D(SampleDimension dimension, int instance = 0) => throw new InvalidOperationException($"asked for {dimension}");
    public override void Get2D(SampleDimension dimension, int instance, out double u, out double v) => throw new InvalidOperationException($"asked for {dimension}");
  }

  [Fact]
  public void A_path_is_not_rouletted_after_a_mirror_or_glass_vertex_nor_before_the_start_bounce()
  {
    var pt = new PathTracing { RussianRouletteStart = 2 };
    var dim = new Rgb(0.1);
    Assert.True(pt.Survives(new Unasked(), 5, delta: true, ref dim));
    Assert.Equal(0.1, dim.G);
    Assert.True(pt.Survives(new Unasked(), 1, delta: false, ref dim));
    Assert.Equal(0.1, dim.G);
  }

  [Fact]
  public void A_path_after_a_smooth_vertex_is_rouletted_by_the_throughput()
  {
    var pt = new PathTracing();
    var sampler = new IndependentSampler();
    sampler.StartPixel(0, 0, 1);
    int survived = 0;
    for (int bounce = 1; bounce < 4001; bounce++)
    {
      var dim = new Rgb(0.25);
      if (pt.Survives(sampler, bounce, delta: false, ref dim))
      {
        survived++;
        Assert.Equal(0.5, dim.R, 12);
      }
    }
    Assert.InRange(survived / 4000.0, 0.46, 0.54);
    Assert.Throws<InvalidOperationException>(() => { var t = new Rgb(0.25); pt.Survives(new Unasked(), 1, delta: false, ref t); });
  }
}
