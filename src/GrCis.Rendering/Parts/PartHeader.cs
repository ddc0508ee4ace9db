namespace Rendering.Parts;

/// <summary>
/// What a part file says about itself. Two parts merge only when everything but
/// <see cref="Index"/> is equal: same scene and settings (<see cref="SettingsHash"/>), size, sampling,
/// seed, gamma, layout and part count.
/// </summary>
public sealed record PartHeader
{
  public required int Width { get; init; }
  public required int Height { get; init; }
  public required int Index { get; init; }
  public required int Count { get; init; }
  public required int SamplesPerPixel { get; init; }
  public required long Seed { get; init; }

  /// <summary>Display gamma the merged PNG is written with.</summary>
  public required double Gamma { get; init; }

  /// <summary>Scene name (built-in) or script file name, for messages.</summary>
  public required string Scene { get; init; }

  /// <summary>Hex SHA-256 of everything that shapes the pixels (scene, script text, parameters, settings).</summary>
  public required string SettingsHash { get; init; }

  public string Layout { get; init; } = PartLayout.Name;

  public int Bands { get; init; } = 3;

  /// <summary>The header with the part index cleared, for comparing parts of one image.</summary>
  internal PartHeader Shared => this with { Index = 0 };
}
