using System;
using System.Collections.Generic;
using System.Linq;
using Rendering;

namespace GrCis.Rendering.Tests.Renderers;

public class SynthesizerTests
{
  /// <summary>Image function: white left of x = edge, black right of it; counts its samples.</summary>
  sealed class EdgeFunction : IImageFunction
  {
    public double Edge = double.PositiveInfinity;
    public int Samples;

    public double Width { get; set; } = 4;
    public double Height { get; set; } = 4;

    public long GetSample(double x, double y, double[] color)
    {
      Samples++;
      double v = x < Edge ? 1.0 : 0.0;
      color[0] = color[1] = color[2] = v;
      return x < Edge ? 1L : 2L;
    }
  }

  [Fact]
  public void Simple_synthesizer_samples_the_pixel_centre_once()
  {
    var f = new EdgeFunction { Edge = 2.5 };
    var s = new SimpleImageSynthesizer { ImageFunction = f };
    double[] c = new double[3];
    s.RenderPixelLinear(2, 0, c);   // centre 2.5 is not < 2.5: black
    Assert.Equal(0.0, c[0]);
    Assert.Equal(1, f.Samples);
  }

  [Fact]
  public void Supersampling_rounds_up_to_a_square_and_averages_the_grid()
  {
    var f = new EdgeFunction { Edge = 1.5 };
    var s = new SupersamplingImageSynthesizer { ImageFunction = f, Supersampling = 5, Jittering = 0.0 };
    Assert.Equal(9, s.Supersampling);
    double[] c = new double[3];
    s.RenderPixelLinear(1, 0, c);   // grid columns at 1+1/6, 1+3/6, 1+5/6: one of three is left of 1.5
    Assert.Equal(1.0 / 3.0, c[0], 12);
    Assert.Equal(9, f.Samples);
  }

  [Fact]
  public void Display_colour_applies_gamma_and_clamps()
  {
    var f = new EdgeFunction();
    var s = new SimpleImageSynthesizer { ImageFunction = f, Gamma = 2.0 };
    double[] c = { 0, 0, 0 };
    s.RenderPixel(0, 0, c);
    Assert.Equal(1.0, c[0]);
    double[] v = { 0.25, 4.0, -1.0 };
    ImageSynthesizer.ApplyGamma(v, 2.0);
    Assert.Equal(new[] { 0.5, 1.0, 0.0 }, v);
  }

  [Fact]
  public void Adaptive_takes_four_samples_where_the_pixel_is_uniform()
  {
    var f = new EdgeFunction();
    var s = new AdaptiveSupersampling { ImageFunction = f, Supersampling = 64 };
    double[] c = new double[3];
    s.RenderPixelLinear(0, 0, c);
    Assert.Equal(4, f.Samples);
    Assert.Equal(1.0, c[0], 12);
  }

  [Fact]
  public void Adaptive_refines_across_an_edge_and_converges_to_the_covered_area()
  {
    var f = new EdgeFunction { Edge = 0.3 };
    var s = new AdaptiveSupersampling { ImageFunction = f, Supersampling = 256, Jittering = 0.0 };
    double[] c = new double[3];
    s.RenderPixelLinear(0, 0, c);
    Assert.True(f.Samples > 4, "an edge inside the pixel must trigger refinement");
    Assert.True(f.Samples < 256 + 85, "uniform sub-cells must not be refined");
    // White covers 30 % of the pixel. A sub-cell whose four samples all fall on one side of the edge
    // is not refined (the price of adaptivity), so the estimate is close, not exact: here 0.25.
    Assert.InRange(c[0], 0.2, 0.4);
  }

  /// <summary>Image function that records where it was sampled.</summary>
  sealed class RecordingFunction : IImageFunction
  {
    public readonly List<(double X, double Y)> Points = new();

    public double Width { get; set; } = 4;
    public double Height { get; set; } = 4;

    public long GetSample(double x, double y, double[] color)
    {
      Points.Add((x, y));
      color[0] = color[1] = color[2] = 0.0;
      return 0L;
    }
  }

  [Theory]
  [InlineData(2)]
  [InlineData(4)]
  [InlineData(7)]
  public void Full_jitter_puts_one_sample_in_each_cell_and_in_each_of_the_n2_columns_and_rows(int n)
  {
    var f = new RecordingFunction();
    var s = new SupersamplingImageSynthesizer { ImageFunction = f, Supersampling = n * n };
    MT.InitThreadData();
    s.RenderPixelLinear(3, 1, new double[3]);
    Assert.Equal(n * n, f.Points.Count);
    Assert.All(f.Points, p => Assert.True(p.X >= 3 && p.X < 4 && p.Y >= 1 && p.Y < 2, $"{p} outside the pixel"));
    Assert.Equal(n * n, f.Points.Select(p => ((int)((p.X - 3) * n), (int)((p.Y - 1) * n))).Distinct().Count());
    Assert.Equal(n * n, f.Points.Select(p => (int)((p.X - 3) * n * n)).Distinct().Count());
    Assert.Equal(n * n, f.Points.Select(p => (int)((p.Y - 1) * n * n)).Distinct().Count());
  }

  [Fact]
  public void An_edge_along_an_axis_is_antialiased_within_one_n2_th_of_its_coverage()
  {
    // Multi-jittered x: whatever the edge's position, at most one of the n² x-strata is cut by it.
    var rnd = new Random(5);
    for (int k = 0; k < 200; k++)
    {
      double edge = 2 + rnd.NextDouble();
      var f = new EdgeFunction { Edge = edge };
      var s = new SupersamplingImageSynthesizer { ImageFunction = f, Supersampling = 16 };
      double[] c = new double[3];
      s.RenderPixelLinear(2, k % 4, c);
      Assert.InRange(c[0], edge - 2 - 1.0 / 16, edge - 2 + 1.0 / 16);
    }
  }

  /// <summary>Image function whose colour is the sampler's next random numbers: any change of stream shows.</summary>
  sealed class RandomFunction : IImageFunction
  {
    public double Width { get; set; } = 4;
    public double Height { get; set; } = 4;

    public long GetSample(double x, double y, double[] color)
    {
      color[0] = MT.rnd.UniformNumber();
      color[1] = MT.rnd.UniformNumber() + x;
      color[2] = MT.rank;
      return 0L;
    }
  }

  [Fact]
  public void Samples_taken_in_passes_that_begin_streams_sum_to_the_one_call_bits()
  {
    var s = new SupersamplingImageSynthesizer { ImageFunction = new RandomFunction(), Supersampling = 16 };
    MT.InitThreadData();
    double[] color = new double[3];
    double[] whole = new double[3], wholeOdd = new double[3];
    s.AccumulateSamples(1, 2, 0, 16, color, whole, wholeOdd);

    double[] parts = new double[3], partsOdd = new double[3];
    foreach ((int first, int end) in new[] { (0, 1), (1, 4), (4, 8), (8, 16) })
      s.AccumulateSamples(1, 2, first, end, color, parts, partsOdd);
    Assert.Equal(whole, parts);
    Assert.Equal(wholeOdd, partsOdd);
    Assert.Equal(Enumerable.Range(0, 16).Sum(), whole[2]);   // every rank once

    Assert.True(SupersamplingImageSynthesizer.IsStreamStart(1, 4) && SupersamplingImageSynthesizer.IsStreamStart(12, 4));
    Assert.Throws<ArgumentOutOfRangeException>(() => s.AccumulateSamples(1, 2, 5, 8, color, parts, partsOdd));
  }

  [Theory]
  [InlineData(4)]
  [InlineData(9)]
  [InlineData(25)]
  public void Every_stream_start_of_a_grid_begins_the_same_stream_in_one_call_as_in_a_pass_of_its_own(int samples)
  {
    // The loop tells stream starts by the sample's place on its diagonal; a pass beginning at each of them (IsStreamStart)
    // must see the numbers the one call saw from there on.
    var s = new SupersamplingImageSynthesizer { ImageFunction = new RandomFunction(), Supersampling = samples };
    MT.InitThreadData();
    double[] color = new double[3];
    double[] whole = new double[3], wholeOdd = new double[3];
    s.AccumulateSamples(3, 1, 0, samples, color, whole, wholeOdd);

    var starts = Enumerable.Range(0, samples).Where(k => SupersamplingImageSynthesizer.IsStreamStart(k, s.SuperXY)).ToList();
    Assert.Equal(s.SuperXY + 1, starts.Count);   // 0, 1 and each later diagonal's first
    double[] parts = new double[3], partsOdd = new double[3];
    for (int k = 0; k < starts.Count; k++)
      s.AccumulateSamples(3, 1, starts[k], k + 1 < starts.Count ? starts[k + 1] : samples, color, parts, partsOdd);
    Assert.Equal(whole, parts);
    Assert.Equal(wholeOdd, partsOdd);
  }
}
