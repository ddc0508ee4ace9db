using System;
using MathSupport;
using Rendering.Imaging;

namespace Rendering;

/// <summary>
/// Shared part of the image synthesizers: size, gamma and the split between the linear pixel
/// colour (what the framebuffer stores) and the display colour (gamma and clamp).
/// </summary>
public abstract class ImageSynthesizer : IRenderer
{
  /// <summary>The image function sampled for each pixel; when null, <see cref="MT.imageFunction"/> is used.</summary>
  public IImageFunction? ImageFunction
  {
    get => imageFunction;
    set
    {
      imageFunction = value;
      Kernel = null;
    }
  }

  IImageFunction? imageFunction;

  /// <summary>
  /// The prepared kernel of <see cref="ImageFunction"/> for the frame being rendered, when it has one: chosen by the
  /// tile renderer once per frame (<see cref="Accel.WhittedKernel.For"/>), cleared when the function changes. It
  /// takes the same samples as the function's <see cref="IImageFunction.GetSample"/>, faster.
  /// </summary>
  internal Accel.WhittedKernel? Kernel;

  /// <inheritdoc/>
  /// <remarks>Default 640 (<see cref="Execution.RenderDefaults.Width"/>).</remarks>
  public int Width { get; set; } = Execution.RenderDefaults.Width;

  /// <inheritdoc/>
  /// <remarks>Default 480 (<see cref="Execution.RenderDefaults.Height"/>).</remarks>
  public int Height { get; set; } = Execution.RenderDefaults.Height;

  /// <summary>Display gamma; values ≤ 0.001 mean linear output.</summary>
  public double Gamma { get; set; } = Execution.RenderDefaults.Gamma;

  /// <summary>Adaptive-refinement level as GrCis's scripts set it (default 1); the library's synthesizers keep it but sample every pixel alike.</summary>
  public int Adaptive { get; set; } = 1;

  /// <summary>Shared progress record, or null; <see cref="RenderRectangle"/> stops before the next row once its <see cref="Progress.Continue"/> is false.</summary>
  public Progress? ProgressData { get; set; }

  /// <summary>Samples one pixel's linear colour; sets <see cref="MT"/>'s pixel and sample rank.</summary>
  public abstract void RenderPixelLinear(int x, int y, double[] color);

  /// <summary>Samples per pixel this synthesizer takes at most.</summary>
  public abstract int SamplesPerPixel { get; }

  /// <summary>
  /// Display colour of one pixel (gamma applied, clamped). GrCis's renderers override this (it was virtual
  /// in every GrCis year); a renderer written here overrides <see cref="RenderPixelLinear"/> instead. When a
  /// class overrides this, the library takes its pixels from here (<see cref="PixelLinear"/>), as GrCis did.
  /// </summary>
  public virtual void RenderPixel(int x, int y, double[] color)
  {
    RenderPixelLinear(x, y, color);
    ApplyGamma(color, Gamma);
  }

  /// <summary>Whether this class overrides <see cref="RenderPixel"/> (a renderer written against GrCis).</summary>
  readonly bool displayPixels;

  /// <summary>Sets up a synthesizer of the default size (640 × 480, gamma 2.2) and notes whether the class overrides <see cref="RenderPixel"/>.</summary>
  protected ImageSynthesizer() => displayPixels = Accel.LibraryTypes.ReturnsDisplayPixels(GetType());

  /// <summary>Whether <paramref name="type"/> overrides this class's virtual method <paramref name="name"/> (not merely hides it).</summary>
  protected static bool Overrides(Type type, string name, Type[] parameters)
  {
    ArgumentNullException.ThrowIfNull(type);
    return Accel.SubclassCheck.OverridesMethod(type, typeof(ImageSynthesizer), name, parameters);
  }

  /// <summary>
  /// The linear colour of pixel (x, y), as the library's loops take it: <see cref="RenderPixelLinear"/>, or, for a
  /// class that overrides <see cref="RenderPixel"/>, its display colour with the gamma taken back off
  /// (<see cref="RemoveGamma"/>), so the image shows exactly what that override returned.
  /// </summary>
  public void PixelLinear(int x, int y, double[] color)
  {
    if (!displayPixels)
    {
      RenderPixelLinear(x, y, color);
      return;
    }
    RenderPixel(x, y, color);
    RemoveGamma(color, Gamma);
  }

  /// <summary>c ← max(c, 0)^gamma: the inverse of <see cref="ApplyGamma"/> on [0, 1]; gamma ≤ 0.001 leaves the colour as it is.</summary>
  public static void RemoveGamma(Span<double> color, double gamma)
  {
    if (Execution.RenderDefaults.IsLinearGamma(gamma))
      return;
    for (int b = 0; b < color.Length; b++)
      color[b] = color[b] > 0.0 ? Math.Pow(color[b], gamma) : 0.0;   // negative or NaN → black, as ApplyGamma
  }

  /// <summary>c ← clamp(c^(1/gamma), 0, 1); gamma ≤ 0.001 leaves the colour linear.</summary>
  public static void ApplyGamma(Span<double> color, double gamma)
  {
    if (Execution.RenderDefaults.IsLinearGamma(gamma))
      return;
    double inv = 1.0 / gamma;
    for (int b = 0; b < color.Length; b++)
      color[b] = color[b] > 0.0 ? Math.Min(Math.Pow(color[b], inv), 1.0) : 0.0;   // negative or NaN → black
  }

  /// <summary>
  /// Renders pixels [x1, x2) × [y1, y2) into <paramref name="image"/> (linear colours), row by row through
  /// <see cref="PixelLinear"/>. Virtual as in GrCis; an override must be re-entrant (threads share the renderer).
  /// </summary>
  public virtual void RenderRectangle(FloatImage image, int x1, int y1, int x2, int y2)
  {
    ArgumentNullException.ThrowIfNull(image);
    double[] color = new double[image.Bands];
    for (int y = y1; y < y2; y++)
    {
      if (ProgressData is { Continue: false })
        return;
      for (int x = x1; x < x2; x++)
      {
        PixelLinear(x, y, color);
        image.SetPixel(x, y, color);
      }
    }
  }

  /// <summary>The image function to sample, with a clear message when none was set.</summary>
  protected IImageFunction Function =>
    ImageFunction ?? MT.imageFunction ?? throw new InvalidOperationException("The renderer has no image function.");
}
