using MathSupport;

namespace Rendering;

/// <summary>Turns an image function into pixels (sampling, gamma). Re-entrant: threads share one instance.</summary>
public interface IRenderer
{
  /// <summary>The image function sampled for each pixel (the tile renderer sets it before rendering).</summary>
  IImageFunction? ImageFunction { get; set; }

  /// <summary>Image width in pixels: the size of the image rendered and of the image function.</summary>
  int Width { get; set; }

  /// <summary>Image height in pixels: the size of the image rendered and of the image function.</summary>
  int Height { get; set; }

  /// <summary>Display gamma applied to the output (1 = linear).</summary>
  double Gamma { get; set; }

  /// <summary>Adaptive-refinement level (0 = off).</summary>
  int Adaptive { get; set; }

  /// <summary>Shared progress record, or null; a renderer stops early when its <see cref="Progress.Continue"/> becomes false.</summary>
  Progress? ProgressData { get; set; }

  /// <summary>Display colour of one pixel: gamma applied and clamped to [0, 1] (as GrCis does).</summary>
  void RenderPixel(int x, int y, double[] color);

  /// <summary>Renders pixels [x1, x2) × [y1, y2) into <paramref name="image"/> (linear colours).</summary>
  void RenderRectangle(Imaging.FloatImage image, int x1, int y1, int x2, int y2);
}
