using Rendering;
using Rendering.Imaging;

namespace GrCis.Hosting;

/// <summary>
/// Wraps the job's renderer for <see cref="Rendering.Execution.TileRenderer"/>: each pixel is computed
/// by the inner renderer exactly as usual, and also copied into the live preview buffer. The pixels the
/// coarse pass rendered exactly (a block's top-left pixel) are taken from the buffer instead.
/// </summary>
internal sealed class PreviewSynthesizer : ImageSynthesizer
{
  readonly ImageSynthesizer inner;
  readonly FloatImage preview;
  readonly bool[]? coarseDone;
  readonly int block, columns;

  /// <param name="coarseDone">Blocks whose top-left pixel the coarse pass finished (row-major), or null.</param>
  public PreviewSynthesizer(ImageSynthesizer inner, FloatImage preview, bool[]? coarseDone = null, int block = 1)
  {
    this.inner = inner;
    this.preview = preview;
    this.coarseDone = coarseDone;
    this.block = block;
    columns = block > 1 ? (inner.Width + block - 1) / block : 0;
    Width = inner.Width;
    Height = inner.Height;
    Gamma = inner.Gamma;
    Adaptive = inner.Adaptive;
  }

  public override int SamplesPerPixel => inner.SamplesPerPixel;

  public override void RenderPixelLinear(int x, int y, double[] color)
  {
    // The block's corner still holds the coarse pass's value: nothing else writes there before this pixel.
    if (coarseDone != null && x % block == 0 && y % block == 0 && coarseDone[y / block * columns + x / block])
    {
      int p = preview.PixelIndex(x, y);
      for (int b = 0; b < color.Length; b++)
        color[b] = preview.Data[p + b];
      return;
    }
    inner.RenderPixelLinear(x, y, color);
    preview.SetPixel(x, y, color);
  }
}
