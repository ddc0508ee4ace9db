using System;
using Rendering.Execution;

namespace Rendering;

/// <summary>
/// n×n stratified supersampling: the pixel is split into a regular grid and each cell is sampled
/// at its centre moved by up to <see cref="Jittering"/> of the cell size (0 = regular grid, 1 = full jitter).
/// Within its cell a sample is multi-jittered (Chiu, Shirley and Wang 1994): the cells of one column take
/// different n-ths of the column's width, and those of one row different n-ths of its height, so the samples'
/// x and y alone are each stratified into n² strata too. An edge along either axis (a light's border, a wall)
/// is then antialiased to within 1/n² of its exact coverage, where plain jitter leaves errors of about 1/n.
/// Derives from <see cref="SimpleImageSynthesizer"/> as in GrCis (code may hold it as one).
/// </summary>
public class SupersamplingImageSynthesizer : SimpleImageSynthesizer
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

  /// <summary>A supersampling synthesizer, one sample per pixel until <see cref="Supersampling"/> is set; full jitter (<see cref="Jittering"/> 1).</summary>
  /// <param name="adaptive">Kept in <see cref="ImageSynthesizer.Adaptive"/> (default 1).</param>
  public SupersamplingImageSynthesizer(int adaptive = 1) : base(adaptive) { }

  /// <summary>The n × n samples of the grid (<see cref="Supersampling"/>).</summary>
  public override int SamplesPerPixel => Supersampling;

  /// <summary>The mean of the pixel's n × n jittered samples (see <see cref="SupersamplingImageSynthesizer"/>).</summary>
  /// <param name="x">Pixel column, 0 at the left.</param>
  /// <param name="y">Pixel row, 0 at the top.</param>
  /// <param name="color">Receives the linear colour, one value per band.</param>
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
  /// <see cref="SampleCell"/>) also to <paramref name="oddSum"/>. Sample 1 and each diagonal's first sample start a
  /// random stream of their own (<see cref="MT.StartStream"/>), so the samples of a pixel may be taken in several
  /// calls that each begin at such a sample (<see cref="IsStreamStart"/>), and the sums are those of one call.
  /// <paramref name="color"/> is scratch.
  /// </summary>
  /// <exception cref="ArgumentOutOfRangeException"><paramref name="first"/> does not begin a stream.</exception>
  // Not inlined into RenderPixelLinear: the start of a render compiles both at tier 1 (tier-0 RenderPixelLinear calls
  // this one), and inlined, the sample loop was compiled twice; one call per pixel costs nothing beside its samples.
  [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.NoInlining)]
  public void AccumulateSamples(int x, int y, int first, int end, double[] color, Span<double> sum, Span<double> oddSum)
  {
    if (!IsStreamStart(first, superXY))
      throw new ArgumentOutOfRangeException(nameof(first), first, "A pass must begin at sample 0, 1 or a diagonal's first sample.");
    IImageFunction f = Function;
    Accel.WhittedKernel? kernel = Kernel;
    int bands = color.Length, n = superXY;
    double step = 1.0 / n;
    double amplitude = Math.Clamp(Jittering, 0.0, 1.0) * step;
    double origin = 0.5 * (step - amplitude);
    var rnd = MT.rnd;

    MT.StartPixel(x, y, n * n);
    // Per-pixel random rotations of the sub-cell order (below), so the early passes are not all at one side of their cells.
    uint pattern = amplitude > 0.0 && n > 1 ? Strata.Pattern(PixelDimension) : 0u;
    int rotateX = (int)(pattern % (uint)n), rotateY = (int)((pattern >> 16) % (uint)n);
    // Sample s = d·n + k lies on diagonal d in row k, column (k + d) mod n (SampleCell), kept incrementally.
    int d = first / n, k = first - d * n;
    for (int s = first; s < end; s++)
    {
      if (s > 0)
      {
        // IsStreamStart(s, n) without its division: s % n == 0 is k == 0 here.
        if (s == 1 || k == 0)
          MT.StartStream(s);
        else
          MT.StartSample(s);
      }
      int i = k + d;
      if (i >= n)
        i -= n;
      double sx = x + origin + i * step, sy = y + origin + k * step;
      if (amplitude > 0.0)
      {
        // The n-th of its cell the sample takes follows its diagonal: a column (a row) meets every diagonal once,
        // so its cells take distinct n-ths (n² strata in x and in y), and the even diagonals take every other n-th,
        // so each half-image of the noise estimate is stratified the same way at half the resolution.
        int subX = d + rotateX, subY = d + rotateY;
        if (subX >= n)
          subX -= n;
        if (subY >= n)
          subY -= n;
        sx += amplitude * (subX + rnd.UniformNumber()) * step;
        sy += amplitude * (subY + rnd.UniformNumber()) * step;
      }
      // The frame's prepared kernel, when the function has one, called directly (inlined).
      if (kernel != null)
        kernel.Sample(sx, sy, color);
      else
        f.GetSample(sx, sy, color);
      for (int b = 0; b < bands; b++)
        sum[b] += color[b];
      if ((d & 1) != 0)
        for (int b = 0; b < bands; b++)
          oddSum[b] += color[b];
      if (++k == n)
      {
        k = 0;
        d++;
      }
    }
  }

  /// <summary>
  /// Whether sample <paramref name="s"/> of an n×n grid begins a random stream: sample 0 (the pixel's), sample 1 (so a
  /// one-sample pass can come first) and each diagonal's first. Fresh streams cost a reseed, so there is one per
  /// diagonal, not one per sample.
  /// </summary>
  public static bool IsStreamStart(int s, int n) => s <= 1 || s % n == 0;

  /// <summary>The <see cref="Strata"/> dimension of the sample positions in the pixel (the rotations of their sub-cell order): purpose 0.</summary>
  static readonly uint PixelDimension = Strata.Dimension(SampleDimension.PixelGrid, 0);

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
