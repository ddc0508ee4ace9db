namespace Rendering;

/// <summary>One sample per pixel, at the pixel centre.</summary>
public class SimpleImageSynthesizer : ImageSynthesizer
{
  public SimpleImageSynthesizer(int adaptive = 1) => Adaptive = adaptive;

  public override int SamplesPerPixel => 1;

  public override void RenderPixelLinear(int x, int y, double[] color)
  {
    MT.StartPixel(x, y, 1);
    if (Kernel is Accel.WhittedKernel kernel)
      kernel.Sample(x + 0.5, y + 0.5, color);
    else
      Function.GetSample(x + 0.5, y + 0.5, color);
  }
}
