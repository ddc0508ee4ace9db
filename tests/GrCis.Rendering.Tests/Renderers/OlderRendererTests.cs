using System;
using MathSupport;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;
using Utilities;

namespace GrCis.Rendering.Tests.Renderers;

/// <summary>
/// Renderers written against GrCis (2017/18 onward): they override the virtual <c>RenderPixel</c> of
/// <c>SimpleImageSynthesizer</c> or <c>SupersamplingImageSynthesizer</c>, which returns the display colour
/// (gamma applied), and hold a supersampling renderer as a <c>SimpleImageSynthesizer</c>. The image shows what
/// their <c>RenderPixel</c> returns, as GrCis's bitmap did.
/// </summary>
public class OlderRendererTests
{
  // ---------------------------------------------------------------- a student's renderers, GrCis style

  /// <summary>Regular 2×2 supersampling of 2018, written from scratch in RenderPixel.</summary>
  class MyGridSynthesizer : SimpleImageSynthesizer
  {
    public override void RenderPixel(int x, int y, double[] color)
    {
      int bands = color.Length;
      Array.Clear(color, 0, bands);
      double[] tmp = new double[bands];
      MT.StartPixel(x, y, 4);
      for (int j = 0; j < 2; j++)
        for (int i = 0; i < 2; i++)
        {
          MT.imageFunction.GetSample(x + 0.25 + 0.5 * i, y + 0.25 + 0.5 * j, tmp);
          MT.NextSample();
          Util.ColorAdd(tmp, color);
        }
      if (Gamma > 0.001)
      {
        double g = 1.0 / Gamma;
        for (int b = 0; b < bands; b++)
          color[b] = Arith.Clamp(Math.Pow(color[b] * 0.25, g), 0.0, 1.0);
      }
      else
        Util.ColorMul(0.25, color);
    }
  }

  /// <summary>A supersampler that shows red and blue swapped: the library's pixel, then a change of the display colour.</summary>
  sealed class MySwappingSynthesizer : SupersamplingImageSynthesizer
  {
    public override void RenderPixel(int x, int y, double[] color)
    {
      base.RenderPixel(x, y, color);
      (color[0], color[2]) = (color[2], color[0]);
    }
  }

  /// <summary>A renderer that paints a display-space pattern without sampling at all.</summary>
  sealed class MyPatternSynthesizer : SimpleImageSynthesizer
  {
    public override void RenderPixel(int x, int y, double[] color)
    {
      double v = ((x + y) & 1) == 0 ? 0.5 : 0.25;
      color[0] = v;
      color[1] = 1.0;
      color[2] = 0.0;
    }
  }

  /// <summary>A method that only hides RenderPixel (no override): the library renders as the base class.</summary>
  sealed class MyHidingSynthesizer : SimpleImageSynthesizer
  {
    public new void RenderPixel(int x, int y, double[] color) => Array.Fill(color, 0.5);
  }

  /// <summary>A renderer that leaves every other row of its rectangles black (this port's rectangle type).</summary>
  sealed class MyStripesSynthesizer : SimpleImageSynthesizer
  {
    public override void RenderRectangle(FloatImage image, int x1, int y1, int x2, int y2)
    {
      base.RenderRectangle(image, x1, y1, x2, y2);
      var black = new double[image.Bands];
      for (int y = y1; y < y2; y++)
        if ((y & 1) != 0)
          for (int x = x1; x < x2; x++)
            image.SetPixel(x, y, black);
    }
  }

  // ---------------------------------------------------------------- helpers

  static readonly IRayScene Scene = Scenes.Create("Five balls");

  static FloatImage Render(ImageSynthesizer renderer)
  {
    renderer.Width = 40;
    renderer.Height = 30;
    return TileRenderer.Render(Scene, new RayTracing(Scene), renderer, new RenderOptions { Threads = 2, TileSize = 8, Seed = 5 });
  }

  /// <summary>The display colour of a pixel of a linear image, as the renderer's gamma shows it.</summary>
  static double[] Shown(FloatImage image, int x, int y, double gamma)
  {
    var c = new double[image.Bands];
    image.GetPixel(x, y, c);
    ImageSynthesizer.ApplyGamma(c, gamma);
    return c;
  }

  static void AssertShownAlike(FloatImage expected, FloatImage actual, double gamma, Func<double[], double[]>? change = null)
  {
    for (int y = 0; y < expected.Height; y++)
      for (int x = 0; x < expected.Width; x++)
      {
        double[] e = Shown(expected, x, y, gamma), a = Shown(actual, x, y, gamma);
        if (change != null)
          e = change(e);
        for (int b = 0; b < e.Length; b++)
          Assert.True(Math.Abs(e[b] - a[b]) < 1e-5, $"pixel ({x}, {y}) band {b}: {e[b]} expected, {a[b]} shown");
      }
  }

  // ---------------------------------------------------------------- tests

  [Fact]
  public void A_supersampling_renderer_is_a_simple_image_synthesizer_as_in_GrCis()
  {
    SimpleImageSynthesizer r = new SupersamplingImageSynthesizer { Supersampling = 4, Jittering = 0.0 };
    var alone = new SupersamplingImageSynthesizer { Supersampling = 4, Jittering = 0.0 };
    Assert.Equal(Render(alone).Data, Render(r).Data);
    Assert.Equal(4, r.SamplesPerPixel);
  }

  [Fact]
  public void RenderPixel_through_a_simple_synthesizer_variable_samples_as_the_supersampler()
  {
    var f = new RayTracing(Scene);
    f.Width = 40;
    f.Height = 30;
    SimpleImageSynthesizer r = new SupersamplingImageSynthesizer { Supersampling = 4, Jittering = 0.0, ImageFunction = f };
    var simple = new SimpleImageSynthesizer { ImageFunction = f };
    double[] grid = new double[3], centre = new double[3], expected = new double[3];
    int differ = 0;
    MT.InitThreadData();
    MT.SetRendering(Scene, f, r);
    try
    {
      for (int y = 0; y < 30; y += 3)
        for (int x = 0; x < 40; x++)
        {
          r.RenderPixel(x, y, grid);
          ((SupersamplingImageSynthesizer)r).RenderPixelLinear(x, y, expected);
          ImageSynthesizer.ApplyGamma(expected, r.Gamma);
          Assert.Equal(expected, grid);
          simple.RenderPixel(x, y, centre);
          if (!centre.AsSpan().SequenceEqual(grid))
            differ++;
        }
    }
    finally
    {
      MT.SetRendering(null, null, null);
    }
    // On the balls' edges the four samples differ from the centre one.
    Assert.True(differ > 0);
  }

  [Fact]
  public void A_RenderPixel_written_from_scratch_renders_as_the_library_grid()
  {
    FloatImage theirs = Render(new MyGridSynthesizer());
    FloatImage ours = Render(new SupersamplingImageSynthesizer { Supersampling = 4, Jittering = 0.0 });
    AssertShownAlike(ours, theirs, 2.2);
  }

  [Fact]
  public void A_RenderPixel_override_that_calls_the_base_changes_what_is_shown()
  {
    FloatImage theirs = Render(new MySwappingSynthesizer { Supersampling = 4 });
    FloatImage ours = Render(new SupersamplingImageSynthesizer { Supersampling = 4 });
    AssertShownAlike(ours, theirs, 2.2, c => new[] { c[2], c[1], c[0] });
  }

  [Theory]
  [InlineData(2.2)]
  [InlineData(1.0)]
  [InlineData(0.0)]
  public void The_image_shows_exactly_the_display_colour_RenderPixel_returns(double gamma)
  {
    FloatImage image = Render(new MyPatternSynthesizer { Gamma = gamma });
    Assert.Equal(0.5, Shown(image, 0, 0, gamma)[0], 6);
    Assert.Equal(0.25, Shown(image, 1, 0, gamma)[0], 6);
    Assert.Equal(1.0, Shown(image, 1, 0, gamma)[1], 6);
    Assert.Equal(0.0, Shown(image, 1, 0, gamma)[2]);
  }

  [Fact]
  public void A_RenderRectangle_override_is_what_the_tiles_render()
  {
    FloatImage image = Render(new MyStripesSynthesizer());
    FloatImage plain = Render(new SimpleImageSynthesizer());
    var c = new double[3];
    var p = new double[3];
    for (int y = 0; y < image.Height; y++)
      for (int x = 0; x < image.Width; x++)
      {
        image.GetPixel(x, y, c);
        plain.GetPixel(x, y, p);
        Assert.Equal((y & 1) != 0 ? new double[3] : p, c);
      }
  }

  [Fact]
  public void A_method_that_only_hides_RenderPixel_leaves_the_library_sampling()
  {
    Assert.Equal(Render(new SimpleImageSynthesizer()).Data, Render(new MyHidingSynthesizer()).Data);
  }
}
