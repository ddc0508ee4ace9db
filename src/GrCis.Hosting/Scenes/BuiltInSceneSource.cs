using Rendering;

namespace GrCis.Hosting;

/// <summary>One of the classic GrCis scenes from <see cref="Scenes"/>.</summary>
public sealed class BuiltInSceneSource : ISceneSource
{
  public BuiltInSceneSource(string name, string? param = null)
  {
    DisplayName = name;
    Param = param ?? "";
  }

  public string DisplayName { get; }

  /// <summary>Parameter text for the scenes that take one (Two spheres, Sphere flake, Cubes).</summary>
  public string Param { get; }

  public string OutputStem => Slug.Of(DisplayName);

  /// <summary>GrCis's parameter help for the scene, or null when it takes none.</summary>
  public string? ToolTip => TooltipOf(DisplayName);

  /// <summary>Parameter help of the built-in scene <paramref name="name"/> (what its initializer parses), or null when it takes none.</summary>
  public static string? TooltipOf(string name) => name switch
  {
    "Two spheres" => "n=<double> (index of refraction of the glass ball, default 1.6)",
    "Sphere flake" => "depth=<int> (default 5), coef=<double> (default 0.4), n=<double> (default 1.6), mat=mirror|glass (else diffuse)",
    "Cubes" => "n=<double> (default 1.6), mat=mirror|glass (else diffuse)",
    _ => null,
  };

  public IRayScene CreateScene() => Scenes.Create(DisplayName, Param);
}
