using System;
using System.Collections.Generic;
using Rendering;

namespace GrCis.Interactive;

/// <summary>The classic GrCis scenes of <see cref="Scenes"/> as catalog entries, with their parameter help.</summary>
public static class BuiltInScenes
{
  /// <summary>GrCis's default scene, selected when nothing else was asked for.</summary>
  public static string DefaultName => Scenes.DefaultSceneName;

  /// <summary>Parameter help of a built-in scene, or null when it takes no parameters.</summary>
  public static string? Tooltip(string name) => GrCis.Hosting.BuiltInSceneSource.TooltipOf(name);

  /// <summary>Adds every scene of <see cref="Scenes.Names"/> in GrCis's order; returns how many were added.</summary>
  public static int AddTo(SceneCatalog catalog)
  {
    ArgumentNullException.ThrowIfNull(catalog);
    int added = 0;
    foreach (string name in Scenes.Names)
    {
      // Skip a name that is already listed (AddTo called twice): the catalog would rename it "(2)".
      if (catalog.Find(name) is { Kind: SceneEntryKind.BuiltIn })
        continue;
      string scene = name;
      catalog.AddBuiltIn(name, param => Scenes.Create(scene, param), Tooltip(name));
      added++;
    }
    return added;
  }
}
