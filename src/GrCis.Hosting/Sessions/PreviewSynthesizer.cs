using Rendering;
using Rendering.Imaging;

namespace GrCis.Hosting;

/// <summary>
/// Wraps the job's renderer for <see cref="Rendering.Execution.TileRenderer"/>: each pixel is computed
/// by the inner renderer exactly as usual, and also copied into the live preview buffer.
/// </summary>
internal sealed class PreviewSynthesizer : ImageSynthesizer
{
  readonly ImageSynthesizer inner;
  readonly FloatImage preview;

  public PreviewSynthesizer(ImageSynthesizer inner, FloatImage preview)
  {
    this.inner = inner;
    this.preview = preview;
    Width = inner.Width;
    Height = inner.Height;
    Gamma = inner.Gamma;
    Adaptive = inner.Adaptive;
  }

  public override int SamplesPerPixel => inner.SamplesPerPixel;

  public override void RenderPixelLinear(int x, int y, double[] color)
  {
    inner.RenderPixelLinear(x, y, color);
    preview.SetPixel(x, y, color);
  }
}
