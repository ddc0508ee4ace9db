using Rendering;
using Rendering.Imaging;

namespace GrCis.Hosting;

/// <summary>
/// Wraps the job's renderer for <see cref="Rendering.Execution.TileRenderer"/>: each pixel is computed
/// by the inner renderer exactly as usual (through its own RenderRectangle when it overrides that), and also
/// copied into the live preview buffer. The pixels the coarse pass rendered exactly (a block's top-left
/// pixel) are taken from the buffer instead.
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
    innerRectangles = Rendering.Accel.FrontEndRules.RendersOwnRectangles(inner.GetType());
  }

  /// <summary>The inner renderer renders its rectangles its own way (a subclass overrides RenderRectangle).</summary>
  readonly bool innerRectangles;

  public override void RenderRectangle(FloatImage image, int x1, int y1, int x2, int y2)
  {
    if (!innerRectangles)
    {
      base.RenderRectangle(image, x1, y1, x2, y2);
      return;
    }
    inner.RenderRectangle(image, x1, y1, x2, y2);
    var color = new double[image.Bands];
    for (int y = y1; y < y2; y++)
      for (int x = x1; x < x2; x++)
      {
        image.GetPixel(x, y, color);
        preview.SetPixel(x, y, color);
      }
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
    inner.PixelLinear(x, y, color);
    preview.SetPixel(x, y, color);
  }
}
