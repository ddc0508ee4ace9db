using System;
using GrCis.Hosting;
using Rendering;

namespace GrCis.Interactive;

/// <summary>A built-in entry of the catalog (a scene made by code) as a scene source of the hosting path.</summary>
internal sealed class CatalogSceneSource : ISceneSource
{
  readonly Func<string, IRayScene> factory;
  readonly string param;

  public CatalogSceneSource(SceneEntry entry, string param)
  {
    factory = entry.Factory ?? throw new ArgumentException($"Scene '{entry.Name}' is not built in.", nameof(entry));
    DisplayName = entry.Name;
    this.param = param;
  }

  public string DisplayName { get; }

  public string OutputStem => Slug.Of(DisplayName);

  public IRayScene CreateScene() => factory(param);
}
