using System;
using Rendering.Imaging;

namespace Rendering.Execution;

/// <summary>
/// A render's noise estimate, pixel by pixel, from two half-images: the pixel's samples on the even and on the
/// odd diagonals of its grid (<see cref="SupersamplingImageSynthesizer.SampleCell"/>). Both halves are stratified
/// like the whole, and independent, so the squared difference of their means estimates the variance of the
/// pixel's value — what is left of the noise at this sample count — without the overestimate a per-sample
/// variance gives stratified samples. Pixels of fewer than 2×2 samples, or of renderers that take their
/// samples otherwise, have no estimate (NaN).
/// </summary>
public sealed class NoiseImage
{
  readonly float[] variance;

  /// <summary>An image of the given size with no estimate yet (every pixel NaN).</summary>
  /// <param name="width">Width in pixels.</param>
  /// <param name="height">Height in pixels.</param>
  public NoiseImage(int width, int height)
  {
    Variance = new FloatImage(width, height, 1);
    variance = Variance.Data;
    Array.Fill(variance, float.NaN);
  }

  /// <summary>Estimated variance of each pixel's value (mean over its colour bands); NaN = no estimate.</summary>
  public FloatImage Variance { get; }

  /// <summary>Width in pixels.</summary>
  public int Width => Variance.Width;

  /// <summary>Height in pixels.</summary>
  public int Height => Variance.Height;

  /// <summary>
  /// Records pixel (x, y) from the sum of its first <paramref name="samples"/> samples of an n×n grid and the sum of
  /// those on odd diagonals. With a samples of mean A and b of mean B, the variance of the mean of all a + b is
  /// estimated as (A − B)²·a·b/(a + b)².
  /// </summary>
  public void Set(int x, int y, ReadOnlySpan<double> sum, ReadOnlySpan<double> oddSum, int samples, int n)
  {
    if ((uint)x >= (uint)Width || (uint)y >= (uint)Height || n < 1)
      return;
    int diagonals = samples / n, rest = samples - diagonals * n;
    int odd = diagonals / 2 * n + ((diagonals & 1) != 0 ? rest : 0), even = samples - odd;
    if (odd == 0 || even == 0)
      return;
    double v = 0.0;
    for (int b = 0; b < sum.Length; b++)
    {
      double d = (sum[b] - oddSum[b]) / even - oddSum[b] / odd;
      v += d * d;
    }
    variance[y * Width + x] = (float)(v / sum.Length * even * odd / ((double)samples * samples));
  }

  /// <summary>The estimated root-mean-square error of the image over the pixels that have an estimate; null if none has.</summary>
  public double? Rmse()
  {
    double total = 0.0;
    long count = 0;
    foreach (float v in variance)
      if (!float.IsNaN(v))
      {
        total += v;
        count++;
      }
    return count > 0 ? Math.Sqrt(total / count) : null;
  }

  /// <summary>The estimated error of pixel (x, y): the standard deviation of its value; NaN = none.</summary>
  public double StandardErrorAt(int x, int y) => Math.Sqrt(variance[y * Width + x]);

  /// <summary>The estimated error of each pixel (standard deviation of its value; NaN = none), as a one-band image.</summary>
  public FloatImage StandardError()
  {
    var image = new FloatImage(Width, Height, 1);
    for (int y = 0; y < Height; y++)
      for (int x = 0; x < Width; x++)
        image.Data[y * Width + x] = (float)StandardErrorAt(x, y);
    return image;
  }
}
