using System;
using System.Globalization;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Hosting;

/// <summary>What a render did: size, samples, threads, time, rays and hits, tiles; its <see cref="ToString"/> is the statistics line.</summary>
public sealed record RenderStatistics
{
  public TimeSpan Elapsed { get; init; }
  public int Width { get; init; }
  public int Height { get; init; }
  public int Threads { get; init; }
  public int SamplesPerPixel { get; init; }

  /// <summary>Rays traced (primary, shadow, secondary), counted per thread into the render's context: exact whatever the image function and threads.</summary>
  public long Rays { get; init; }

  /// <summary>Rays that hit something (a blocked shadow ray counts).</summary>
  public long Intersections { get; init; }

  /// <summary>
  /// Estimated root-mean-square error of the pixels' linear values (<see cref="NoiseImage"/>): how far the image
  /// probably is from the converged one. Null when the render took no estimate (fewer than 2×2 samples per pixel).
  /// </summary>
  public double? Noise { get; init; }

  /// <summary><see cref="Noise"/> relative to the image's mean value.</summary>
  public double? RelativeNoise { get; init; }

  public int TilesDone { get; init; }
  public int TilesTotal { get; init; }

  /// <summary>
  /// The statistics of a tile render by <paramref name="renderer"/> with <paramref name="options"/>: rays, hits and
  /// the noise estimate from its <paramref name="context"/>, threads as many as were useful (at most one per tile).
  /// </summary>
  /// <param name="image">The rendered image, which the noise is relative to.</param>
  public static RenderStatistics Of(ImageSynthesizer renderer, RenderOptions options, RenderContext context, TimeSpan elapsed,
                                    int tilesDone, int tilesTotal, FloatImage image)
  {
    double? noise = context.Noise?.Rmse();
    double mean = noise != null ? Mean(image) : 0.0;
    return new()
    {
      Elapsed = elapsed,
      Width = renderer.Width,
      Height = renderer.Height,
      Threads = Math.Clamp(options.EffectiveThreads, 1, Math.Max(1, tilesTotal)),
      SamplesPerPixel = renderer.SamplesPerPixel,
      Rays = context.Rays,
      Intersections = context.Hits,
      TilesDone = tilesDone,
      TilesTotal = tilesTotal,
      Noise = noise,
      RelativeNoise = noise != null && mean > 0.0 ? noise / mean : null,
    };
  }

  static double Mean(FloatImage image)
  {
    double sum = 0.0;
    foreach (float v in image.Data)
      if (float.IsFinite(v))
        sum += v;
    return sum / Math.Max(1, image.Data.Length);
  }

  public double RaysPerSecond => Elapsed.TotalSeconds > 0 ? Rays / Elapsed.TotalSeconds : 0.0;

  public override string ToString()
  {
    string line = string.Create(CultureInfo.InvariantCulture,
      $"{Width}x{Height}, {SamplesPerPixel} spp, {Threads} thread{(Threads == 1 ? "" : "s")}, {Elapsed.TotalSeconds:0.00} s, {Rays / 1e6:0.###} M rays, {Intersections / 1e6:0.###} M intersections, {RaysPerSecond / 1e6:0.##} M rays/s");
    if (Noise is double noise)
      line += string.Create(CultureInfo.InvariantCulture, $", noise {noise:0.####} RMSE") +
              (RelativeNoise is double r ? string.Create(CultureInfo.InvariantCulture, $" ({r * 100:0.##} %)") : "");
    return TilesDone < TilesTotal ? line + $", stopped at {TilesDone}/{TilesTotal} tiles" : line;
  }
}
