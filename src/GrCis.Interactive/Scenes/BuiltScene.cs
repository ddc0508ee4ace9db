using Rendering;

namespace GrCis.Interactive;

/// <summary>A scene ready to render: the scene itself plus whatever its script chose through the context.</summary>
public sealed class BuiltScene
{
  public BuiltScene(SceneEntry entry, string param, IRayScene scene)
  {
    Entry = entry;
    Param = param;
    Scene = scene;
  }

  public SceneEntry Entry { get; }

  public string Param { get; }

  public IRayScene Scene { get; }

  public SceneOverrides Overrides { get; init; } = new();

  /// <summary>Image function the script chose (CTX_ALGORITHM), else null = ray tracing from the settings.</summary>
  public IImageFunction? ImageFunction { get; init; }

  /// <summary>Renderer the script chose (CTX_SYNTHESIZER), else null = from the settings.</summary>
  public IRenderer? Renderer { get; init; }

  public string? Tooltip { get; init; }
}
