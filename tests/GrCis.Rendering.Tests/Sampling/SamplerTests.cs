using System;
using System.Collections.Generic;
using System.Linq;
using Rendering;
using Rendering.Execution;

namespace GrCis.Rendering.Tests.Sampling;

public class SamplerTests
{
  public static TheoryData<SamplerKind> Kinds => new() { SamplerKind.CorrelatedMultiJitter, SamplerKind.Independent, SamplerKind.Sobol };

  static Sampler At(SamplerKind kind, int x, int y, int count, long seed = 3)
  {
    Sampler s = Sampler.Create(kind, seed, frame: 2);
    s.StartPixel(x, y, count);
    return s;
  }

  [Theory]
  [MemberData(nameof(Kinds))]
  public void Every_value_lies_in_the_unit_interval(SamplerKind kind)
  {
    foreach (int count in new[] { 1, 7, 16, 64 })
      for (int px = 0; px < 6; px++)
      {
        Sampler s = At(kind, px, 2 * px + 1, count);
        for (int i = 0; i < count; i++)
        {
          s.StartPixelSample(px, 2 * px + 1, i);
          foreach (SampleDimension d in Enum.GetValues<SampleDimension>())
            for (int instance = 0; instance < 3; instance++)
            {
              double a = s.Get1D(d, instance);
              s.Get2D(d, instance, out double u, out double v);
              Assert.InRange(a, 0.0, Math.BitDecrement(1.0));
              Assert.InRange(u, 0.0, Math.BitDecrement(1.0));
              Assert.InRange(v, 0.0, Math.BitDecrement(1.0));
            }
        }
      }
  }

  [Theory]
  [MemberData(nameof(Kinds))]
  public void Values_depend_only_on_pixel_sample_and_dimension_not_on_the_order_asked(SamplerKind kind)
  {
    Sampler a = At(kind, 5, 9, 16), b = At(kind, 5, 9, 16);
    a.StartPixelSample(5, 9, 7);
    b.StartPixelSample(5, 9, 7);
    double lobe = a.Get1D(SampleDimension.PathLobe, 2);
    double roulette = a.Get1D(SampleDimension.PathRoulette, 2);
    // Asked the other way round, after other dimensions, on another sampler of the same seed and frame.
    b.Get2D(SampleDimension.Lens, out _, out _);
    Assert.Equal(roulette, b.Get1D(SampleDimension.PathRoulette, 2));
    Assert.Equal(lobe, b.Get1D(SampleDimension.PathLobe, 2));
  }

  [Theory]
  [MemberData(nameof(Kinds))]
  public void Named_dimensions_are_independent_of_each_other(SamplerKind kind)
  {
    // Over many pixels and samples, two dimensions (and two instances of one) are uncorrelated.
    const int count = 16;
    var pairs = new List<(SampleDimension, int, SampleDimension, int)>
    {
      (SampleDimension.PathLobe, 0, SampleDimension.PathRoulette, 0),
      (SampleDimension.PathLightPick, 1, SampleDimension.PathLobe, 1),
      (SampleDimension.PathDirection, 0, SampleDimension.PathDirection, 1),
      (SampleDimension.Lens, 0, SampleDimension.GlossyReflection, 0),
    };
    foreach ((SampleDimension da, int ia, SampleDimension db, int ib) in pairs)
    {
      var xs = new List<double>();
      var ys = new List<double>();
      for (int px = 0; px < 40; px++)
      {
        Sampler s = At(kind, px, 3, count);
        for (int i = 0; i < count; i++)
        {
          s.StartPixelSample(px, 3, i);
          xs.Add(s.Get1D(da, ia));
          ys.Add(s.Get1D(db, ib));
        }
      }
      Assert.NotEqual(xs, ys);
      Assert.InRange(Correlation(xs, ys), -0.1, 0.1);
    }
  }

  static double Correlation(List<double> a, List<double> b)
  {
    double ma = a.Average(), mb = b.Average();
    double cov = a.Zip(b, (x, y) => (x - ma) * (y - mb)).Sum();
    double va = a.Sum(x => (x - ma) * (x - ma)), vb = b.Sum(y => (y - mb) * (y - mb));
    return cov / Math.Sqrt(va * vb);
  }

  [Fact]
  public void Correlated_multi_jitter_stratifies_a_pixel_in_2D_and_in_each_coordinate()
  {
    const int n = 4, count = n * n;
    for (int px = 0; px < 5; px++)
    {
      Sampler s = At(SamplerKind.CorrelatedMultiJitter, px, 11, count);
      var cells = new HashSet<(int, int)>();
      var columns = new HashSet<int>();
      var rows = new HashSet<int>();
      var strata1D = new HashSet<int>();
      for (int i = 0; i < count; i++)
      {
        s.StartPixelSample(px, 11, i);
        s.Get2D(SampleDimension.PathDirection, 1, out double u, out double v);
        cells.Add(((int)(u * n), (int)(v * n)));
        columns.Add((int)(u * count));
        rows.Add((int)(v * count));
        strata1D.Add((int)(s.Get1D(SampleDimension.PathRoulette, 1) * count));
      }
      Assert.Equal(count, cells.Count);
      Assert.Equal(count, columns.Count);
      Assert.Equal(count, rows.Count);
      Assert.Equal(count, strata1D.Count);
    }
  }

  [Fact]
  public void Correlated_multi_jitter_gives_the_values_Strata_gave_by_purpose_number()
  {
    // The sampler keeps the images of distributed ray tracing and area lights: same values as Strata's numbered purposes.
    var cmj = (CorrelatedMultiJitterSampler)At(SamplerKind.CorrelatedMultiJitter, 7, 8, 9, seed: 12);
    cmj.StartPixelSample(7, 8, 5);
    using (WorkerContext.Begin(null, new DefaultRayScene(), new RayTracing(), null, new RenderOptions { Seed = 12, Frame = 2 }))
    {
      MT.StartPixel(7, 8, 9);
      MT.StartSample(5);
      foreach ((SampleDimension d, uint purpose) in new[] { (SampleDimension.Lens, 1u), (SampleDimension.GlossyReflection, 3u), (SampleDimension.PathDirection, 5u) })
      {
        Strata.Sample2D(Strata.Dimension(purpose, 3), out double u, out double v);
        cmj.Get2D(d, 3, out double cu, out double cv);
        Assert.Equal(u, cu);
        Assert.Equal(v, cv);
        Assert.Equal(Strata.Sample1D(Strata.Dimension(purpose, 3)), cmj.Get1D(d, 3));
      }
    }
  }

  [Fact]
  public void Sobol_first_points_are_the_known_sequence()
  {
    // The first eight points of Sobol's dimensions 0 and 1 (unscrambled).
    double[,] expected =
    {
      { 0, 0 }, { 0.5, 0.5 }, { 0.25, 0.75 }, { 0.75, 0.25 }, { 0.125, 0.625 }, { 0.625, 0.125 }, { 0.375, 0.375 }, { 0.875, 0.875 },
    };
    for (uint i = 0; i < 8; i++)
    {
      Assert.Equal(expected[i, 0], SobolSampler.Sobol(0, i) / 4294967296.0);
      Assert.Equal(expected[i, 1], SobolSampler.Sobol(1, i) / 4294967296.0);
    }
  }

  [Fact]
  public void Sobol_points_of_a_pixel_form_a_0_2_net_after_scrambling()
  {
    // 16 samples: every elementary interval of area 1/16 (16×1, 8×2, 4×4, 2×8, 1×16) holds exactly one point.
    const int count = 16;
    for (int px = 0; px < 5; px++)
    {
      Sampler s = At(SamplerKind.Sobol, px, 4, count);
      var points = new List<(double U, double V)>();
      for (int i = 0; i < count; i++)
      {
        s.StartPixelSample(px, 4, i);
        s.Get2D(SampleDimension.PathLightPoint, 2, out double u, out double v);
        points.Add((u, v));
      }
      for (int cx = 1; cx <= count; cx *= 2)
      {
        int cy = count / cx;
        Assert.Equal(count, points.Select(p => ((int)(p.U * cx), (int)(p.V * cy))).Distinct().Count());
      }
      // And the 1D values are stratified into 16.
      var strata = new HashSet<int>();
      for (int i = 0; i < count; i++)
      {
        s.StartPixelSample(px, 4, i);
        strata.Add((int)(s.Get1D(SampleDimension.PathLobe, 0) * count));
      }
      Assert.Equal(count, strata.Count);
    }
  }

  [Fact]
  public void Independent_sampler_is_not_stratified_but_uniform()
  {
    // Over a pixel's 16 samples, some 1/16 strata repeat (no stratification), while the mean over many is 1/2.
    int repeats = 0;
    double sum = 0.0;
    int n = 0;
    for (int px = 0; px < 20; px++)
    {
      Sampler s = At(SamplerKind.Independent, px, 0, 16);
      var strata = new HashSet<int>();
      for (int i = 0; i < 16; i++)
      {
        s.StartPixelSample(px, 0, i);
        double a = s.Get1D(SampleDimension.PathLobe);
        strata.Add((int)(a * 16));
        sum += a;
        n++;
      }
      repeats += 16 - strata.Count;
    }
    Assert.True(repeats > 20, $"{repeats} repeated strata");
    Assert.InRange(sum / n, 0.45, 0.55);
  }

  [Theory]
  [InlineData("cmj", SamplerKind.CorrelatedMultiJitter)]
  [InlineData("Independent", SamplerKind.Independent)]
  [InlineData("SOBOL", SamplerKind.Sobol)]
  public void Sampler_names_parse_in_any_case_and_round_trip(string name, SamplerKind kind)
  {
    Assert.True(Sampler.TryParse(name, out SamplerKind parsed));
    Assert.Equal(kind, parsed);
    Assert.Equal(name.ToLowerInvariant(), Sampler.NameOf(kind));
    Assert.Equal(kind, Sampler.Create(kind).Kind);
    Assert.False(Sampler.TryParse("halton", out _));
  }
}
