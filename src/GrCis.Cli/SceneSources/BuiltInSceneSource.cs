using Rendering;

namespace GrCis.Cli.SceneSources;

/// <summary>One of the classic GrCis scenes from <see cref="Scenes"/>.</summary>
public sealed class BuiltInSceneSource : ISceneSource
{
  public BuiltInSceneSource(string name) => DisplayName = name;

  public string DisplayName { get; }

  public string OutputStem => Slug.Of(DisplayName);

  public IRayScene CreateScene() => Scenes.Create(DisplayName);
}
