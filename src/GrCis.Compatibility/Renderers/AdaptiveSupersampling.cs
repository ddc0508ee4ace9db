using System;

namespace Rendering;

/// <summary>
/// Adaptive supersampling: each pixel starts with a 2×2 grid; a cell whose four sub-samples differ
/// (different hash, or colour difference at least <see cref="Threshold"/>) is split again, down to
/// at most <see cref="Supersampling"/> samples per pixel. Leaves are averaged by area.
/// </summary>
public class AdaptiveSupersampling : ImageSynthesizer
{
  int maxDepth = 2;

  /// <summary>Colour difference (max over bands) that triggers refinement.</summary>
  public double Threshold { get; set; } = 0.004;

  /// <summary>Jitter of each sample inside its cell, 0 to 1.</summary>
  public double Jittering { get; set; } = 1.0;

  /// <summary>Most samples per pixel; rounded up to a power of four (4, 16, 64, …).</summary>
  public int Supersampling
  {
    get => 1 << (2 * maxDepth);
    set
    {
      if (value < 1)
        throw new ArgumentOutOfRangeException(nameof(value), value, "Supersampling must be at least 1.");
      int d = 0;
      while ((1 << (2 * d)) < value && d < 6)
        d++;
      maxDepth = d;
    }
  }

  public AdaptiveSupersampling(double threshold = 0.004)
  {
    Threshold = threshold;
    Supersampling = 16;
  }

  public override int SamplesPerPixel => Supersampling;

  public override void RenderPixelLinear(int x, int y, double[] color)
  {
    MT.StartPixel(x, y, Supersampling);
    if (maxDepth == 0)
    {
      Function.GetSample(x + 0.5, y + 0.5, color);
      return;
    }
    Span<double> sum = stackalloc double[color.Length];
    Cell(x, y, 1.0, 1, color, sum);
    for (int b = 0; b < color.Length; b++)
      color[b] = sum[b];
  }

  /// <summary>Samples the four quadrants of a cell; refines those that disagree; adds area-weighted colour to <paramref name="sum"/>.</summary>
  void Cell(double x0, double y0, double size, int depth, double[] tmp, Span<double> sum)
  {
    IImageFunction f = Function;
    int bands = tmp.Length;
    double half = 0.5 * size;
    Span<double> colors = stackalloc double[4 * bands];
    Span<long> hashes = stackalloc long[4];
    double amplitude = Math.Clamp(Jittering, 0.0, 1.0) * half;
    double offset = 0.5 * (half - amplitude);

    for (int q = 0; q < 4; q++)
    {
      double sx = x0 + (q & 1) * half + offset;
      double sy = y0 + (q >> 1) * half + offset;
      if (amplitude > 0.0)
      {
        sx += amplitude * MT.rnd.UniformNumber();
        sy += amplitude * MT.rnd.UniformNumber();
      }
      hashes[q] = f.GetSample(sx, sy, tmp);
      MT.NextSample();
      tmp.AsSpan(0, bands).CopyTo(colors.Slice(q * bands, bands));
    }

    bool differ = false;
    if (depth < maxDepth)
      for (int q = 1; q < 4 && !differ; q++)
      {
        differ = hashes[q] != hashes[0];
        for (int b = 0; b < bands && !differ; b++)
          differ = Math.Abs(colors[q * bands + b] - colors[b]) >= Threshold;
      }

    double area = half * half;
    for (int q = 0; q < 4; q++)
    {
      if (differ)
        Cell(x0 + (q & 1) * half, y0 + (q >> 1) * half, half, depth + 1, tmp, sum);
      else
        for (int b = 0; b < bands; b++)
          sum[b] += area * colors[q * bands + b];
    }
  }
}
