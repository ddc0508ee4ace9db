using System;
using Rendering.Execution;

namespace Rendering;

/// <summary>
/// n×n stratified supersampling: the pixel is split into a regular grid and each cell is sampled
/// at its centre moved by up to <see cref="Jittering"/> of the cell size (0 = regular grid, 1 = full jitter).
/// </summary>
public class SupersamplingImageSynthesizer : ImageSynthesizer
{
  /// <summary>Samples per row and column of a pixel's grid.</summary>
  protected int superXY = 1;

  /// <summary>Grid cells per pixel side.</summary>
  public int SuperXY => superXY;

  /// <summary>Samples per pixel; rounded up to the next square.</summary>
  public int Supersampling
  {
    get => superXY * superXY;
    set
    {
      if (value < 1)
        throw new ArgumentOutOfRangeException(nameof(value), value, "Supersampling must be at least 1.");
      int k = 1;
      while (k * k < value)
        k++;
      superXY = k;
    }
  }

  /// <summary>Fraction of a grid cell the sample may move, 0 to 1.</summary>
  public double Jittering { get; set; } = 1.0;

  public SupersamplingImageSynthesizer(int adaptive = 1) => Adaptive = adaptive;

  public override int SamplesPerPixel => Supersampling;

  public override void RenderPixelLinear(int x, int y, double[] color)
  {
    int bands = color.Length;
    Span<double> sum = stackalloc double[bands];
    Span<double> odd = stackalloc double[bands];
    AccumulateSamples(x, y, 0, Supersampling, color, sum, odd);
    FinishPixel(sum, color);
    if (ShadingScratch.Current.Noise is NoiseImage noise)
      noise.Set(x, y, sum, odd, Supersampling, superXY);
  }

  /// <summary>
  /// Takes samples <paramref name="first"/> to <paramref name="end"/> − 1 of pixel (x, y) and adds each one's
  /// colour to <paramref name="sum"/>, in sample order, and the colours of the odd diagonals (see
  /// <see cref="SampleCell"/>) also to <paramref name="oddSum"/>. Each sample draws from its own stream
  /// (<see cref="MT.StartSample"/>), so the samples of a pixel may be taken in several calls and the sums are
  /// those of one call. <paramref name="color"/> is scratch.
  /// </summary>
  public void AccumulateSamples(int x, int y, int first, int end, double[] color, Span<double> sum, Span<double> oddSum)
  {
    IImageFunction f = Function;
    int bands = color.Length, n = superXY;
    double step = 1.0 / n;
    double amplitude = Math.Clamp(Jittering, 0.0, 1.0) * step;
    double origin = 0.5 * (step - amplitude);
    var rnd = MT.rnd;

    MT.StartPixel(x, y, n * n);
    for (int s = first; s < end; s++)
    {
      if (s > 0)
        MT.StartSample(s);
      (int i, int j, bool oddDiagonal) = SampleCell(s, n);
      double sx = x + origin + i * step, sy = y + origin + j * step;
      if (amplitude > 0.0)
      {
        sx += amplitude * rnd.UniformNumber();
        sy += amplitude * rnd.UniformNumber();
      }
      f.GetSample(sx, sy, color);
      for (int b = 0; b < bands; b++)
        sum[b] += color[b];
      if (oddDiagonal)
        for (int b = 0; b < bands; b++)
          oddSum[b] += color[b];
    }
  }

  /// <summary>The pixel's colour from the sum of all its samples.</summary>
  public void FinishPixel(ReadOnlySpan<double> sum, double[] color)
  {
    double mul = 1.0 / (superXY * superXY);
    for (int b = 0; b < color.Length; b++)
      color[b] = sum[b] * mul;
  }

  /// <summary>
  /// The grid cell of sample <paramref name="s"/> of an n×n pixel grid: the samples go diagonal by diagonal
  /// (cell (k + d) mod n, k for sample d·n + k), so the first n samples, and any whole diagonals, cover every
  /// row and every column of the pixel once. The even and the odd diagonals are the two half-images of the
  /// noise estimate.
  /// </summary>
  public static (int I, int J, bool OddDiagonal) SampleCell(int s, int n)
  {
    int d = s / n, k = s - d * n;
    int i = k + d;
    if (i >= n)
      i -= n;
    return (i, k, (d & 1) != 0);
  }
}
