using System;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Hosting;

/// <summary>
/// One pass of a progressive render (<see cref="RenderSession.Progressive"/>): for each pixel, samples
/// <see cref="First"/> to <see cref="End"/> − 1 of the job's n×n supersampling, added to the pixel's running sums.
/// The sums grow in sample order, so after the last pass each pixel is, bit for bit, what the renderer gives in
/// one go. Every pixel's current mean goes to the live preview, and its noise estimate to <see cref="Noise"/>.
/// </summary>
internal sealed class SamplePassSynthesizer : ImageSynthesizer
{
  readonly SupersamplingImageSynthesizer inner;
  readonly FloatImage live;
  readonly double[] sums, oddSums;

  public SamplePassSynthesizer(SupersamplingImageSynthesizer inner, FloatImage live, NoiseImage noise)
  {
    this.inner = inner;
    this.live = live;
    Noise = noise;
    Width = inner.Width;
    Height = inner.Height;
    Gamma = inner.Gamma;
    Adaptive = inner.Adaptive;
    sums = new double[live.Data.Length];
    oddSums = new double[live.Data.Length];
  }

  /// <summary>First sample of this pass.</summary>
  public int First { get; set; }

  /// <summary>One past the last sample of this pass.</summary>
  public int End { get; set; }

  public NoiseImage Noise { get; }

  public override int SamplesPerPixel => inner.SamplesPerPixel;

  /// <summary>
  /// The sample counts after each pass for an n×n grid: 1 sample first (an image at once), then the first
  /// diagonal (n samples), then twice as many each pass up to n². Whole diagonals keep each pass's samples
  /// spread over the pixel and its half-images (the noise estimate) balanced, and every pass begins a random
  /// stream (<see cref="SupersamplingImageSynthesizer.IsStreamStart"/>).
  /// </summary>
  public static int[] PassEnds(int n)
  {
    var ends = new System.Collections.Generic.List<int> { 1 };
    for (int end = n; end < n * n; end *= 2)
      if (end > ends[^1])
        ends.Add(end);
    if (n * n > ends[^1])
      ends.Add(n * n);
    return ends.ToArray();
  }

  public override void RenderPixelLinear(int x, int y, double[] color)
  {
    int p = y * Width + x, bands = color.Length;
    Span<double> sum = sums.AsSpan(p * bands, bands), odd = oddSums.AsSpan(p * bands, bands);
    inner.AccumulateSamples(x, y, First, End, color, sum, odd);
    int n = inner.SuperXY;
    if (End == n * n)
      inner.FinishPixel(sum, color);   // the renderer's own last step, so the final pixel is its value exactly
    else
      for (int b = 0; b < bands; b++)
        color[b] = sum[b] / End;
    Noise.Set(x, y, sum, odd, End, n);
    live.SetPixel(x, y, color);
  }

}
