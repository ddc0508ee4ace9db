using System;

namespace Rendering.Imaging;

/// <summary>
/// Linear floating-point framebuffer: <see cref="Bands"/> interleaved channels per pixel,
/// rows stored top row first (the order PNG uses; PFM output flips on write).
/// </summary>
public sealed class FloatImage
{
  /// <summary>Upper bound on Width * Height * Bands, so the buffer always fits one array.</summary>
  public const long MaxSamples = 1L << 30;

  /// <summary>Width in pixels.</summary>
  public int Width { get; }
  /// <summary>Height in pixels.</summary>
  public int Height { get; }
  /// <summary>Channels per pixel (3 for RGB).</summary>
  public int Bands { get; }

  /// <summary>Row-major samples, top row first; sample (x, y, band) is at (y * Width + x) * Bands + band.</summary>
  public float[] Data { get; }

  /// <summary>A black image (every sample 0).</summary>
  /// <param name="width">Width in pixels, positive.</param>
  /// <param name="height">Height in pixels, positive.</param>
  /// <param name="bands">Channels per pixel, positive (default 3).</param>
  /// <exception cref="ArgumentOutOfRangeException">A size or the band count is not positive.</exception>
  /// <exception cref="ArgumentException">The image would have more than <see cref="MaxSamples"/> samples.</exception>
  public FloatImage(int width, int height, int bands = 3)
  {
    Validate(width, height, bands);
    Width = width;
    Height = height;
    Bands = bands;
    Data = new float[(long)width * height * bands];
  }

  /// <summary>Wraps <paramref name="data"/> without copying.</summary>
  public FloatImage(int width, int height, int bands, float[] data)
  {
    Validate(width, height, bands);
    ArgumentNullException.ThrowIfNull(data);
    long expected = (long)width * height * bands;
    if (data.Length != expected)
      throw new ArgumentException($"Pixel buffer has {data.Length} samples but {width}x{height}x{bands} needs {expected}.", nameof(data));
    Width = width;
    Height = height;
    Bands = bands;
    Data = data;
  }

  /// <summary>Sample <paramref name="band"/> of pixel (<paramref name="x"/>, <paramref name="y"/>); (0, 0) is the top-left pixel.</summary>
  /// <exception cref="ArgumentOutOfRangeException">A coordinate or the band lies outside the image.</exception>
  public float this[int x, int y, int band]
  {
    get => Data[SampleIndex(x, y, band)];
    set => Data[SampleIndex(x, y, band)] = value;
  }

  /// <summary>Index of band 0 of pixel (x, y) in <see cref="Data"/>.</summary>
  public int PixelIndex(int x, int y)
  {
    if ((uint)x >= (uint)Width)
      throw new ArgumentOutOfRangeException(nameof(x), x, $"x must be in 0..{Width - 1}.");
    if ((uint)y >= (uint)Height)
      throw new ArgumentOutOfRangeException(nameof(y), y, $"y must be in 0..{Height - 1}.");
    return (y * Width + x) * Bands;
  }

  /// <summary>Copies the first <see cref="Bands"/> channels of pixel (x, y) into <paramref name="color"/>.</summary>
  public void GetPixel(int x, int y, Span<double> color)
  {
    int i = PixelIndex(x, y);
    if (color.Length < Bands)
      throw new ArgumentException($"Color has {color.Length} channels, image has {Bands}.", nameof(color));
    for (int b = 0; b < Bands; b++)
      color[b] = Data[i + b];
  }

  /// <summary>A new array with the <see cref="Bands"/> channels of pixel (x, y).</summary>
  /// <exception cref="ArgumentOutOfRangeException">The pixel lies outside the image.</exception>
  public double[] GetPixel(int x, int y)
  {
    double[] color = new double[Bands];
    GetPixel(x, y, color);
    return color;
  }

  /// <summary>Stores the first <see cref="Bands"/> channels of <paramref name="color"/> (extra channels are ignored).</summary>
  public void SetPixel(int x, int y, ReadOnlySpan<double> color)
  {
    int i = PixelIndex(x, y);
    if (color.Length < Bands)
      throw new ArgumentException($"Color has {color.Length} channels, image has {Bands}.", nameof(color));
    for (int b = 0; b < Bands; b++)
      Data[i + b] = (float)color[b];
  }

  private int SampleIndex(int x, int y, int band)
  {
    if ((uint)band >= (uint)Bands)
      throw new ArgumentOutOfRangeException(nameof(band), band, $"band must be in 0..{Bands - 1}.");
    return PixelIndex(x, y) + band;
  }

  private static void Validate(int width, int height, int bands)
  {
    if (width <= 0)
      throw new ArgumentOutOfRangeException(nameof(width), width, "Image width must be positive.");
    if (height <= 0)
      throw new ArgumentOutOfRangeException(nameof(height), height, "Image height must be positive.");
    if (bands <= 0)
      throw new ArgumentOutOfRangeException(nameof(bands), bands, "Number of bands must be positive.");
    if ((long)width * height * bands > MaxSamples)
      throw new ArgumentException($"Image {width}x{height}x{bands} exceeds the limit of {MaxSamples} samples.");
  }
}
