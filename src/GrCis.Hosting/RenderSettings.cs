using System;
using Rendering;
using Rendering.Accel;
using Rendering.Execution;

namespace GrCis.Hosting;

/// <summary>
/// The settings of one render, the same for every front end (<c>grcis render</c>/<c>animate</c>, the demo,
/// the studio): image size, sampling, the ray-tracing switches, execution. Immutable, so a finished render
/// keeps exactly the settings it was made with. Which of them a user gave explicitly, and so win over a
/// scene script's choices, is said separately (<see cref="GivenSettings"/>, <see cref="Precedence"/>).
/// </summary>
public sealed record RenderSettings
{
  /// <summary>Upper limit of samples per pixel: a 256×256 grid (Blender's default final render takes 4096).</summary>
  public const int MaxSamplesPerPixel = 65536;

  /// <summary>Image width in pixels.</summary>
  public int Width { get; init; } = RenderDefaults.Width;

  /// <summary>Image height in pixels.</summary>
  public int Height { get; init; } = RenderDefaults.Height;

  /// <summary>Samples per pixel: 1 = pixel centre; more = an n×n grid (rounded up to a square).</summary>
  public int SamplesPerPixel { get; init; } = RenderDefaults.SamplesPerPixel;

  /// <summary>Jitter of supersamples inside their grid cell: 0 = regular grid, 1 = full.</summary>
  public double Jitter { get; init; } = 1.0;

  public bool Shadows { get; init; } = true;

  public bool Reflections { get; init; } = true;

  public bool Refractions { get; init; } = true;

  /// <summary>The image function used when the scene script does not choose one.</summary>
  public RenderAlgorithm Algorithm { get; init; } = RenderAlgorithm.RayTracing;

  /// <summary>Ray queries: the prepared BVH fast path (default) or GrCis's faithful path.</summary>
  public AccelMode Accel { get; init; } = AccelMode.Bvh;

  /// <summary>Display gamma of the shown and saved 8-bit image (1 = linear); the render itself is linear.</summary>
  public double Gamma { get; init; } = RenderDefaults.Gamma;

  /// <summary>Worker threads; 0 = one per processor.</summary>
  public int Threads { get; init; }

  /// <summary>Seed of all sample randomness (same seed ⇒ same image, whatever the threads).</summary>
  public long Seed { get; init; }

  /// <summary>The sample generator of the render's random decisions (lens, area lights, glossy and path vertices).</summary>
  public SamplerKind Sampler { get; init; } = SamplerKind.CorrelatedMultiJitter;

  /// <summary>Tile side in pixels (the image does not depend on it).</summary>
  public int TileSize { get; init; } = RenderDefaults.TileSize;

  /// <summary>Scene time for a still of an animated scene; null = the script's time, else the animation's start.</summary>
  public double? Time { get; init; }

  /// <summary>Samples actually taken per pixel (the grid is square).</summary>
  public int EffectiveSamplesPerPixel
  {
    get
    {
      if (SamplesPerPixel <= 1)
        return 1;
      int k = (int)Math.Ceiling(Math.Sqrt(SamplesPerPixel));
      while (k * k < SamplesPerPixel)
        k++;
      return k * k;
    }
  }

  /// <summary>The worker threads this asks for (<see cref="RenderDefaults.Threads"/>).</summary>
  public int EffectiveThreads => RenderDefaults.Threads(Threads);

  /// <summary>This record, or an <see cref="InvalidSettingException"/> naming the first setting out of range.</summary>
  public RenderSettings Validate()
  {
    if (Width < 1 || Height < 1 || (long)Width * Height > Rendering.Imaging.Rgb8Image.MaxPixels)
      throw new InvalidSettingException(Setting.Size, $"{Width}x{Height}",
        $"both sides must be at least 1 and the image at most {Rendering.Imaging.Rgb8Image.MaxPixels} pixels");
    if (SamplesPerPixel < 1)
      throw new InvalidSettingException(Setting.SamplesPerPixel, SamplesPerPixel, "must be at least 1");
    if (SamplesPerPixel > MaxSamplesPerPixel)
      throw new InvalidSettingException(Setting.SamplesPerPixel, SamplesPerPixel, $"at most {MaxSamplesPerPixel} (a 256x256 grid per pixel)");
    if (!(Jitter >= 0.0 && Jitter <= 1.0))
      throw new InvalidSettingException(Setting.Jitter, Jitter, "must be between 0 and 1");
    if (Threads < 0)
      throw new InvalidSettingException(Setting.Threads, Threads, "must be 0 (one per processor) or more");
    if (!(Gamma > 0.0) || double.IsInfinity(Gamma))
      throw new InvalidSettingException(Setting.Gamma, Gamma, "must be a positive number (1 = linear)");
    if (TileSize < 1)
      throw new InvalidSettingException(Setting.TileSize, TileSize, "must be at least 1");
    return this;
  }

  /// <summary>Execution options for <see cref="TileRenderer"/>.</summary>
  public RenderOptions ToRenderOptions(int frame = 0) => new()
  {
    Threads = EffectiveThreads,
    TileSize = TileSize,
    Seed = Seed,
    Frame = frame,
    Sampler = Sampler,
  };

  /// <summary>The renderer these settings select: one centred sample, or an n×n (jittered) grid.</summary>
  public ImageSynthesizer CreateSynthesizer() => RenderSetup.CreateSynthesizer(Width, Height, SamplesPerPixel, Jitter, Gamma);

  /// <summary>
  /// The <see cref="Algorithm"/>'s image function with these switches and query mode. <paramref name="scene"/>
  /// null = unbound: it shades <c>MT.scene</c>, so each render worker uses its own clone of an animated scene.
  /// </summary>
  public RayTracing CreateImageFunction(IRayScene? scene = null)
  {
    RayTracing rt = Algorithm switch
    {
      RenderAlgorithm.Distributed => new Rendering.Distributed.DistributedRayTracing(scene),
      RenderAlgorithm.Path => new PathTracing(scene),
      _ => new RayTracing(scene),
    };
    RenderSetup.ApplySwitches(rt, Shadows, Reflections, Refractions);
    rt.Accel = Accel;
    return rt;
  }
}
