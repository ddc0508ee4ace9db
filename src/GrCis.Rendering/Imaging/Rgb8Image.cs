using System;

namespace Rendering.Imaging;

/// <summary>
/// 8-bit sRGB-encoded image: 3 interleaved bytes (R, G, B) per pixel, rows top row first.
/// This is what PNG files are decoded to and compared as.
/// </summary>
public sealed class Rgb8Image
{
  /// <summary>Upper bound on Width * Height, so the RGB buffer always fits one array.</summary>
  public const long MaxPixels = 1L << 28;

  /// <summary>Width in pixels.</summary>
  public int Width { get; }
  /// <summary>Height in pixels.</summary>
  public int Height { get; }

  /// <summary>Row-major RGB bytes; pixel (x, y) starts at (y * Width + x) * 3.</summary>
  public byte[] Data { get; }

  /// <summary>Bytes per row: 3 × <see cref="Width"/>.</summary>
  public int Stride => Width * 3;

  /// <summary>A black image (every byte 0).</summary>
  /// <param name="width">Width in pixels, positive.</param>
  /// <param name="height">Height in pixels, positive.</param>
  /// <exception cref="ArgumentOutOfRangeException">A size is not positive.</exception>
  /// <exception cref="ArgumentException">The image would have more than <see cref="MaxPixels"/> pixels.</exception>
  public Rgb8Image(int width, int height)
  {
    Validate(width, height);
    Width = width;
    Height = height;
    Data = new byte[width * height * 3];
  }

  /// <summary>Wraps <paramref name="data"/> without copying.</summary>
  public Rgb8Image(int width, int height, byte[] data)
  {
    Validate(width, height);
    ArgumentNullException.ThrowIfNull(data);
    int expected = width * height * 3;
    if (data.Length != expected)
      throw new ArgumentException($"Pixel buffer has {data.Length} bytes but {width}x{height} RGB needs {expected}.", nameof(data));
    Width = width;
    Height = height;
    Data = data;
  }

  /// <summary>The red, green and blue bytes of pixel (x, y); (0, 0) is the top-left pixel.</summary>
  /// <exception cref="ArgumentOutOfRangeException">The pixel lies outside the image.</exception>
  public (byte R, byte G, byte B) GetPixel(int x, int y)
  {
    int i = PixelIndex(x, y);
    return (Data[i], Data[i + 1], Data[i + 2]);
  }

  /// <summary>Sets the red, green and blue bytes of pixel (x, y).</summary>
  /// <exception cref="ArgumentOutOfRangeException">The pixel lies outside the image.</exception>
  public void SetPixel(int x, int y, byte r, byte g, byte b)
  {
    int i = PixelIndex(x, y);
    Data[i] = r;
    Data[i + 1] = g;
    Data[i + 2] = b;
  }

  /// <summary>Index of the red byte of pixel (x, y) in <see cref="Data"/>.</summary>
  /// <exception cref="ArgumentOutOfRangeException">The pixel lies outside the image.</exception>
  public int PixelIndex(int x, int y)
  {
    if ((uint)x >= (uint)Width)
      throw new ArgumentOutOfRangeException(nameof(x), x, $"x must be in 0..{Width - 1}.");
    if ((uint)y >= (uint)Height)
      throw new ArgumentOutOfRangeException(nameof(y), y, $"y must be in 0..{Height - 1}.");
    return (y * Width + x) * 3;
  }

  /// <summary>True when both images have the same size and identical bytes.</summary>
  public bool ContentEquals(Rgb8Image? other) =>
    other is not null && other.Width == Width && other.Height == Height && Data.AsSpan().SequenceEqual(other.Data);

  /// <summary>
  /// Quantizes a linear framebuffer with <see cref="DisplayEncoding"/>: v^(1/gamma), clamped to [0, 1],
  /// then rounded (default) or truncated. gamma = 1 writes values unchanged, as GrCis's bitmap output does.
  /// Rendered images are written with <see cref="DisplayEncoding.ForRender"/> (truncation).
  /// </summary>
  public static Rgb8Image FromFloatImage(FloatImage image, double gamma = 1.0, Quantization quantization = Quantization.Round)
  {
    ArgumentNullException.ThrowIfNull(image);
    return new DisplayEncoding(gamma, quantization).Encode(image);
  }

  private static void Validate(int width, int height)
  {
    if (width <= 0)
      throw new ArgumentOutOfRangeException(nameof(width), width, "Image width must be positive.");
    if (height <= 0)
      throw new ArgumentOutOfRangeException(nameof(height), height, "Image height must be positive.");
    if ((long)width * height > MaxPixels)
      throw new ArgumentException($"Image {width}x{height} exceeds the limit of {MaxPixels} pixels.");
  }
}
