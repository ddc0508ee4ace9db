using System;

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
    IImageFunction f = Function;
    int bands = color.Length;
    Span<double> sum = stackalloc double[bands];
    double step = 1.0 / superXY;
    double amplitude = Math.Clamp(Jittering, 0.0, 1.0) * step;
    double origin = 0.5 * (step - amplitude);
    var rnd = MT.rnd;

    MT.StartPixel(x, y, Supersampling);
    for (int j = 0; j < superXY; j++)
    {
      double y0 = y + origin + j * step;
      for (int i = 0; i < superXY; i++)
      {
        double x0 = x + origin + i * step;
        double sx = x0, sy = y0;
        if (amplitude > 0.0)
        {
          sx += amplitude * rnd.UniformNumber();
          sy += amplitude * rnd.UniformNumber();
        }
        f.GetSample(sx, sy, color);
        for (int b = 0; b < bands; b++)
          sum[b] += color[b];
        MT.NextSample();
      }
    }

    double mul = 1.0 / (superXY * superXY);
    for (int b = 0; b < bands; b++)
      color[b] = sum[b] * mul;
  }
}
