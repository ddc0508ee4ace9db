using GrCis.Hosting;

namespace GrCis.Interactive;

/// <summary>
/// A scene of the catalog ready to render: the entry and parameter text it came from and the scene as every front end
/// prepares it (<see cref="PreparedRender"/>: built, the settings resolved by the one precedence rule, set to its time).
/// </summary>
public sealed class BuiltScene
{
  public BuiltScene(SceneEntry entry, string param, PreparedRender prepared)
  {
    Entry = entry;
    Param = param;
    Prepared = prepared;
  }

  public SceneEntry Entry { get; }

  public string Param { get; }

  public PreparedRender Prepared { get; }

  /// <summary>The script's own values (size, supersampling, algorithm, animation range); empty for a built-in scene.</summary>
  public SceneOverrides Overrides { get; init; } = new();

  public string? Tooltip { get; init; }

  /// <summary>A render job for the prepared scene (<see cref="RenderJob.From"/>).</summary>
  public RenderJob ToJob() => RenderJob.From(Prepared, Entry.Name, Param);
}
