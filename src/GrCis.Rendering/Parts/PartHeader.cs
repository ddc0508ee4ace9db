namespace Rendering.Parts;

/// <summary>
/// What a part file says about itself. Two parts merge only when everything but
/// <see cref="Index"/> is equal: same scene and settings (<see cref="SettingsHash"/>), size, sampling,
/// seed, gamma, layout and part count.
/// </summary>
public sealed record PartHeader
{
  /// <summary>Width of the whole image in pixels.</summary>
  public required int Width { get; init; }
  /// <summary>Height of the whole image in pixels.</summary>
  public required int Height { get; init; }
  /// <summary>Which part this is, 0 to <see cref="Count"/> − 1 (<see cref="PartLayout.Tiles"/>).</summary>
  public required int Index { get; init; }
  /// <summary>Number of parts the image is split into.</summary>
  public required int Count { get; init; }
  /// <summary>Samples per pixel of the render.</summary>
  public required int SamplesPerPixel { get; init; }
  /// <summary>The render's seed (<see cref="Execution.RenderOptions.Seed"/>).</summary>
  public required long Seed { get; init; }

  /// <summary>Display gamma the merged PNG is written with.</summary>
  public required double Gamma { get; init; }

  /// <summary>Scene name (built-in) or script file name, for messages.</summary>
  public required string Scene { get; init; }

  /// <summary>Hex SHA-256 of everything that shapes the pixels (scene, script text, parameters, settings).</summary>
  public required string SettingsHash { get; init; }

  /// <summary>Name of the tile layout (default <see cref="PartLayout.Name"/>).</summary>
  public string Layout { get; init; } = PartLayout.Name;

  /// <summary>Channels per pixel (default 3, RGB).</summary>
  public int Bands { get; init; } = 3;

  /// <summary>The header with the part index cleared, for comparing parts of one image.</summary>
  internal PartHeader Shared => this with { Index = 0 };
}
