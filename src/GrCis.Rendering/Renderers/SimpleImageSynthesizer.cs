namespace Rendering;

/// <summary>One sample per pixel, at the pixel centre.</summary>
public class SimpleImageSynthesizer : ImageSynthesizer
{
  /// <summary>A synthesizer taking one sample per pixel, at its centre.</summary>
  /// <param name="adaptive">Kept in <see cref="ImageSynthesizer.Adaptive"/> (default 1).</param>
  public SimpleImageSynthesizer(int adaptive = 1) => Adaptive = adaptive;

  /// <summary>One sample per pixel.</summary>
  public override int SamplesPerPixel => 1;

  /// <summary>The image function's value at the pixel's centre (x + 0.5, y + 0.5).</summary>
  /// <param name="x">Pixel column, 0 at the left.</param>
  /// <param name="y">Pixel row, 0 at the top.</param>
  /// <param name="color">Receives the linear colour, one value per band.</param>
  public override void RenderPixelLinear(int x, int y, double[] color)
  {
    MT.StartPixel(x, y, 1);
    if (Kernel is Accel.WhittedKernel kernel)
      kernel.Sample(x + 0.5, y + 0.5, color);
    else
      Function.GetSample(x + 0.5, y + 0.5, color);
  }
}
