using System;
using System.Globalization;

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

  public int TilesDone { get; init; }
  public int TilesTotal { get; init; }

  public double RaysPerSecond => Elapsed.TotalSeconds > 0 ? Rays / Elapsed.TotalSeconds : 0.0;

  public override string ToString()
  {
    string line = string.Create(CultureInfo.InvariantCulture,
      $"{Width}x{Height}, {SamplesPerPixel} spp, {Threads} thread{(Threads == 1 ? "" : "s")}, {Elapsed.TotalSeconds:0.00} s, {Rays / 1e6:0.###} M rays, {Intersections / 1e6:0.###} M intersections, {RaysPerSecond / 1e6:0.##} M rays/s");
    return TilesDone < TilesTotal ? line + $", stopped at {TilesDone}/{TilesTotal} tiles" : line;
  }
}
