using System;
using Rendering;

namespace GrCis.Interactive;

/// <summary>
/// One line of the scene list: a built-in scene or a script file, the parameter text the user edits,
/// and what the last evaluation reported (tooltip, the script's overrides).
/// </summary>
public sealed class SceneEntry
{
  internal SceneEntry(string name, Func<string, IRayScene> factory, string? tooltip, string defaultParam)
  {
    Name = name;
    Kind = SceneEntryKind.BuiltIn;
    Factory = factory;
    Tooltip = tooltip;
    ParameterText = defaultParam;
  }

  internal SceneEntry(string name, string path)
  {
    Name = name;
    Kind = SceneEntryKind.Script;
    Path = path;
    ParameterText = "";
  }

  /// <summary>Display name: the built-in scene's name or the script's file name without ".cs".</summary>
  public string Name { get; }

  public SceneEntryKind Kind { get; }

  /// <summary>
  /// What a scene list shows: a built-in scene's name, a script's file name ("FiveBalls.cs", "Bezier.cs" beside the
  /// built-in "Bezier"), so scripts stand apart from built-in scenes; unique in its catalog.
  /// </summary>
  public string Label { get; internal set; } = "";

  /// <summary>Full path of the script; null for built-in scenes.</summary>
  public string? Path { get; }

  /// <summary>The user's parameter text ("n=1.5, mat=glass"), handed to the scene as <c>param</c>.</summary>
  public string ParameterText { get; set; }

  /// <summary>Help text for the parameters (CTX_TOOLTIP), known once the scene was evaluated.</summary>
  public string? Tooltip { get; internal set; }

  /// <summary>Size, supersampling, algorithm and time range the script set, known once evaluated.</summary>
  public SceneOverrides? Overrides { get; internal set; }

  internal Func<string, IRayScene>? Factory { get; }

  public override string ToString() => Label.Length > 0 ? Label : Name;
}
