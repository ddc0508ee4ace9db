namespace Rendering.Execution;

/// <summary>How to execute a render: threads, tiles and the seed every sample stream derives from.</summary>
public sealed record RenderOptions
{
  /// <summary>Worker threads; 0 = one per processor.</summary>
  public int Threads { get; init; }

  /// <summary>Tile side in pixels.</summary>
  public int TileSize { get; init; } = RenderDefaults.TileSize;

  /// <summary>Seed of all sample randomness; the image depends on it, not on threads or tile order.</summary>
  public long Seed { get; init; }

  /// <summary>Frame number, mixed into the per-pixel seeds so frames differ.</summary>
  public int Frame { get; init; }

  /// <summary>The sample generator of every random decision (<see cref="Sampler"/>); the default is correlated multi-jitter.</summary>
  public SamplerKind Sampler { get; init; }

  /// <summary>Only these tiles (a part of a scaled-out still, see <see cref="Parts.PartLayout"/>); null = every tile.</summary>
  public System.Collections.Generic.IReadOnlyList<Tile>? Tiles { get; init; }

  /// <summary>The number of worker threads used: <see cref="Threads"/>, or the processor count when it is 0 (or less) (<see cref="RenderDefaults.Threads"/>).</summary>
  public int EffectiveThreads => RenderDefaults.Threads(Threads);
}
