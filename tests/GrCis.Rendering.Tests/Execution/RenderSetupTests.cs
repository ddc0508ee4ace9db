using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Rendering.Tests.Execution;

public class RenderSetupTests
{
  [Fact]
  public void One_sample_is_the_pixel_centre_and_more_is_a_jittered_square_grid()
  {
    ImageSynthesizer one = RenderSetup.CreateSynthesizer(64, 48, 1, 1.0);
    Assert.IsType<SimpleImageSynthesizer>(one);
    Assert.Equal((64, 48, 2.2), (one.Width, one.Height, one.Gamma));

    var grid = Assert.IsType<SupersamplingImageSynthesizer>(RenderSetup.CreateSynthesizer(64, 48, 5, 0.25, gamma: 1.0));
    Assert.Equal(9, grid.SamplesPerPixel);
    Assert.Equal(0.25, grid.Jittering);
    Assert.Equal(1.0, grid.Gamma);
  }

  [Fact]
  public void Ray_tracer_gets_the_three_switches()
  {
    RayTracing rt = RenderSetup.CreateRayTracing(null, shadows: false, reflections: true, refractions: false);
    Assert.Equal((false, true, false), (rt.DoShadows, rt.DoReflections, rt.DoRefractions));
  }

  [Fact]
  public void Display_image_truncates_as_grcis_does()
  {
    var image = new FloatImage(1, 1);
    image.SetPixel(0, 0, new[] { 0.999, 0.5, 0.0 });
    Rgb8Image display = RenderSetup.ToDisplayImage(image, 1.0);
    // 0.999 · 255 = 254.7 and 0.5 · 255 = 127.5: truncated, not rounded.
    Assert.Equal(((byte)254, (byte)127, (byte)0), display.GetPixel(0, 0));
  }
}
