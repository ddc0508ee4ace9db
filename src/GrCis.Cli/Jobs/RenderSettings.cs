using System;
using Rendering.Accel;

namespace GrCis.Cli.Jobs;

/// <summary>Validated settings of one still render (everything but the scene and the output file).</summary>
public sealed record RenderSettings
{
  public ImageSize Size { get; init; } = ImageSize.Default;

  /// <summary>Upper limit of samples per pixel: a 256×256 grid (Blender's default final render takes 4096).</summary>
  public const int MaxSamplesPerPixel = 65536;

  /// <summary>Samples per pixel: 1 = pixel centre; more = an n×n jittered grid (rounded up to a square).</summary>
  public int SamplesPerPixel { get; init; } = 1;

  /// <summary>Jitter of supersamples inside their grid cell, 0 (regular grid) to 1.</summary>
  public double Jitter { get; init; } = 1.0;

  /// <summary>Worker threads; 0 = one per processor.</summary>
  public int Threads { get; init; }

  public long Seed { get; init; }

  /// <summary>Display gamma of the PNG (1 = linear).</summary>
  public double Gamma { get; init; } = 2.2;

  public bool Shadows { get; init; } = true;
  public bool Reflections { get; init; } = true;
  public bool Refractions { get; init; } = true;

  /// <summary>Ray queries: the prepared BVH fast path (default) or GrCis's faithful path (<c>--accel none</c>).</summary>
  public AccelMode Accel { get; init; } = AccelMode.Bvh;

  /// <exception cref="UsageException">A value outside its allowed range.</exception>
  public RenderSettings Validate()
  {
    if (SamplesPerPixel < 1)
      throw new UsageException($"invalid --spp {SamplesPerPixel}: must be at least 1");
    if (SamplesPerPixel > MaxSamplesPerPixel)
      throw new UsageException($"invalid --spp {SamplesPerPixel}: at most {MaxSamplesPerPixel} (a 256x256 grid per pixel)");
    if (!(Jitter >= 0.0 && Jitter <= 1.0))
      throw new UsageException($"invalid --jitter {Jitter}: must be between 0 and 1");
    if (Threads < 0)
      throw new UsageException($"invalid --threads {Threads}: must be 0 (one per processor) or more");
    if (!(Gamma > 0.0) || double.IsInfinity(Gamma))
      throw new UsageException($"invalid --gamma {Gamma}: must be a positive number (1 = linear)");
    return this;
  }

  /// <summary>Samples actually taken per pixel (the grid is square).</summary>
  public int EffectiveSamplesPerPixel
  {
    get
    {
      int k = (int)Math.Ceiling(Math.Sqrt(SamplesPerPixel));
      while (k * k < SamplesPerPixel)
        k++;
      return k * k;
    }
  }
}
