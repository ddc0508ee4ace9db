using System;
using Rendering.Execution;

namespace GrCis.Interactive;

/// <summary>
/// What the demo window's controls set: resolution, sampling, the ray-tracing switches and threading.
/// An immutable record, so a finished render keeps exactly the settings it was made with.
/// </summary>
public sealed record RenderSettings
{
  public int Width { get; init; } = 640;

  public int Height { get; init; } = 480;

  /// <summary>Samples per pixel; more than one selects n×n supersampling (rounded up to a square).</summary>
  public int SamplesPerPixel { get; init; } = 1;

  /// <summary>Jitter of supersamples within their grid cell: 0 = regular grid, 1 = full.</summary>
  public double Jittering { get; init; } = 1.0;

  public bool Shadows { get; init; } = true;

  public bool Reflections { get; init; } = true;

  public bool Refractions { get; init; } = true;

  /// <summary>Display gamma of the shown and saved image (1 = linear); the render itself is linear.</summary>
  public double Gamma { get; init; } = RenderSetup.DefaultGamma;

  /// <summary>Off = render on one thread (GrCis's "multi-threading" switch).</summary>
  public bool Multithreading { get; init; } = true;

  /// <summary>Worker threads when multithreading; 0 = one per processor.</summary>
  public int Threads { get; init; }

  /// <summary>Seed of all sample randomness (same seed ⇒ same image).</summary>
  public long Seed { get; init; }

  public int TileSize { get; init; } = 32;

  /// <summary>Scene time for a still of an animated scene; null = leave the scene's time alone.</summary>
  public double? Time { get; init; }

  public int EffectiveThreads => Multithreading ? (Threads > 0 ? Threads : Environment.ProcessorCount) : 1;

  /// <summary>Throws with a message naming the setting when a value is out of range.</summary>
  public void Validate()
  {
    if (Width < 1 || Height < 1)
      throw new ArgumentOutOfRangeException(nameof(Width), $"Resolution {Width}x{Height} is invalid; both sides must be at least 1.");
    if (SamplesPerPixel < 1)
      throw new ArgumentOutOfRangeException(nameof(SamplesPerPixel), SamplesPerPixel, "Samples per pixel must be at least 1.");
    if (!(Jittering >= 0.0 && Jittering <= 1.0))
      throw new ArgumentOutOfRangeException(nameof(Jittering), Jittering, "Jittering must be between 0 and 1.");
    if (Threads < 0)
      throw new ArgumentOutOfRangeException(nameof(Threads), Threads, "Threads must be 0 (automatic) or positive.");
    if (!(Gamma > 0.0) || double.IsInfinity(Gamma))
      throw new ArgumentOutOfRangeException(nameof(Gamma), Gamma, "Gamma must be a positive number (1 = linear).");
    if (TileSize < 1)
      throw new ArgumentOutOfRangeException(nameof(TileSize), TileSize, "Tile size must be at least 1.");
  }

  /// <summary>This record with a script's size and supersampling overrides applied.</summary>
  public RenderSettings With(SceneOverrides? overrides)
  {
    if (overrides == null)
      return this;
    return this with
    {
      Width = overrides.Width ?? Width,
      Height = overrides.Height ?? Height,
      SamplesPerPixel = overrides.Supersampling ?? SamplesPerPixel,
    };
  }

  /// <summary>Execution options for <see cref="TileRenderer"/>.</summary>
  public RenderOptions ToRenderOptions(int frame = 0) => new()
  {
    Threads = EffectiveThreads,
    TileSize = TileSize,
    Seed = Seed,
    Frame = frame,
  };
}
