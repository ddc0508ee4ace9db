using System;

namespace Rendering.Imaging;

/// <summary>A linear-light RGB framebuffer of floats, row-major, top row first.</summary>
public sealed class FloatImage
{
  public int Width { get; }

  public int Height { get; }

  /// <summary>Colour bands per pixel (3: RGB).</summary>
  public int Bands { get; }

  /// <summary>Pixel data: band b of pixel (x, y) is at <c>(y * Width + x) * Bands + b</c>.</summary>
  public float[] Data { get; }

  public FloatImage(int width, int height, int bands = 3)
  {
    if (width <= 0 || height <= 0)
      throw new ArgumentOutOfRangeException(nameof(width), $"Image size must be positive, got {width}×{height}.");
    if (bands <= 0)
      throw new ArgumentOutOfRangeException(nameof(bands), $"Band count must be positive, got {bands}.");
    if ((long)width * height * bands > Array.MaxLength)
      throw new ArgumentOutOfRangeException(nameof(width), $"Image {width}×{height} is too large.");
    Width = width;
    Height = height;
    Bands = bands;
    Data = new float[width * height * bands];
  }

  /// <summary>Stores a pixel; missing bands repeat the last given one (grey from one value).</summary>
  public void SetPixel(int x, int y, ReadOnlySpan<double> color)
  {
    int o = Offset(x, y);
    for (int b = 0; b < Bands; b++)
      Data[o + b] = (float)color[Math.Min(b, color.Length - 1)];
  }

  public void GetPixel(int x, int y, Span<double> color)
  {
    int o = Offset(x, y);
    for (int b = 0; b < Bands && b < color.Length; b++)
      color[b] = Data[o + b];
  }

  public float this[int x, int y, int band]
  {
    get => Data[Offset(x, y) + band];
    set => Data[Offset(x, y) + band] = value;
  }

  int Offset(int x, int y)
  {
    if ((uint)x >= (uint)Width || (uint)y >= (uint)Height)
      throw new ArgumentOutOfRangeException(nameof(x), $"Pixel ({x}, {y}) is outside the {Width}×{Height} image.");
    return (y * Width + x) * Bands;
  }
}
