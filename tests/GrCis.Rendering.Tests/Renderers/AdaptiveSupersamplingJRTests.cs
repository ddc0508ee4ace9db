using System;
using System.Threading;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Rendering.Tests.Renderers;

/// <summary>GrCis's quad-tree adaptive supersampling: more samples only where neighbours differ.</summary>
public class AdaptiveSupersamplingJRTests
{
  /// <summary>White left of x = 2.5, black right of it; counts its samples.</summary>
  sealed class Edge : IImageFunction
  {
    public int Samples;
    public double Width { get; set; } = 4;
    public double Height { get; set; } = 1;

    public long GetSample(double x, double y, double[] color)
    {
      Interlocked.Increment(ref Samples);
      double v = x < 2.5 ? 1.0 : 0.0;
      Array.Fill(color, v);
      return v > 0 ? 1L : 2L;
    }
  }

  static double[] Pixel(AdaptiveSupersamplingJR jr, Edge f, int x)
  {
    jr.ImageFunction = f;
    var c = new double[3];
    MT.InitThreadData();
    jr.RenderPixelLinear(x, 0, c);
    return c;
  }

  [Fact]
  public void A_flat_pixel_takes_one_sample_and_an_edge_pixel_is_refined_to_its_area()
  {
    var jr = new AdaptiveSupersamplingJR { Supersampling = 16 };
    var flat = new Edge();
    Assert.Equal(new[] { 1.0, 1.0, 1.0 }, Pixel(jr, flat, 0));
    Assert.InRange(flat.Samples, 1, 4);    // the first split always happens; flat quarters stop there

    var edge = new Edge();
    double[] c = Pixel(jr, edge, 2);       // half white
    Assert.True(edge.Samples > 4, $"{edge.Samples} samples");
    Assert.Equal(0.5, c[0], 12);           // the edge at a quarter boundary: exact coverage
  }

  [Fact]
  public void Without_supersampling_one_jittered_sample_per_pixel()
  {
    var jr = new AdaptiveSupersamplingJR();
    var f = new Edge();
    Pixel(jr, f, 1);
    Assert.Equal(1, f.Samples);
  }

  [Fact]
  public void The_image_is_the_same_on_any_number_of_threads()
  {
    IRayScene scene = Scenes.Create("Five balls");
    FloatImage Render(int threads) => TileRenderer.Render(scene, new RayTracing(scene),
      new AdaptiveSupersamplingJR { Supersampling = 16, Width = 48, Height = 36 }, new RenderOptions { Threads = threads, Seed = 3 });
    Assert.Equal(Render(1).Data, Render(2).Data);
  }
}
