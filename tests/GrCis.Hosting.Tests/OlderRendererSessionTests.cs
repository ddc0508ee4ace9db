using System.Threading.Tasks;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Hosting.Tests;

/// <summary>
/// A renderer written against GrCis (overriding RenderPixel, or this port's RenderRectangle) renders the same
/// image in a session (coarse pass, live preview) as in <c>grcis render</c>.
/// </summary>
public class OlderRendererSessionTests
{
  /// <summary>GrCis style: the library's supersampled pixel, shown with red and blue swapped.</summary>
  sealed class MySwappingSynthesizer : SupersamplingImageSynthesizer
  {
    public override void RenderPixel(int x, int y, double[] color)
    {
      base.RenderPixel(x, y, color);
      (color[0], color[2]) = (color[2], color[0]);
    }
  }

  /// <summary>Every other row of its rectangles left black.</summary>
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

  static readonly RenderSettings Small = new() { Width = 48, Height = 32, SamplesPerPixel = 4, TileSize = 16, Threads = 2, Seed = 7 };

  static async Task AssertSessionRendersAsTiles(ImageSynthesizer renderer)
  {
    RenderJob job = RenderJob.Create(Scenes.Create("Five balls"), Small, renderer: renderer);
    Assert.Same(renderer, job.Renderer);
    FloatImage reference = TileRenderer.Render(job.Scene, job.ImageFunction, job.Renderer, Small.ToRenderOptions());
    using var session = new RenderSession(job) { CoarseBlock = 8 };
    FloatImage image = (await session.Start()).Image;
    Assert.Equal(reference.Data, image.Data);
  }

  [Fact]
  public Task A_session_shows_a_GrCis_RenderPixel_override() =>
    AssertSessionRendersAsTiles(new MySwappingSynthesizer { Supersampling = 4 });

  [Fact]
  public Task A_session_renders_through_a_RenderRectangle_override() =>
    AssertSessionRendersAsTiles(new MyStripesSynthesizer());
}
