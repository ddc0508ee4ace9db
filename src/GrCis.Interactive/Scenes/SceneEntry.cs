using System;
using System.IO;
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

  /// <summary>Full path of the script; null for built-in scenes.</summary>
  public string? Path { get; }

  /// <summary>The script text as last read from disk (null until read, and for built-in scenes).</summary>
  public string? Source { get; private set; }

  /// <summary>The user's parameter text ("n=1.5, mat=glass"), handed to the scene as <c>param</c>.</summary>
  public string ParameterText { get; set; }

  /// <summary>Help text for the parameters (CTX_TOOLTIP), known once the scene was evaluated.</summary>
  public string? Tooltip { get; internal set; }

  /// <summary>Size, supersampling and time range the script set, known once evaluated.</summary>
  public SceneOverrides? Overrides { get; internal set; }

  internal Func<string, IRayScene>? Factory { get; }

  /// <summary>Reads the script from disk again (the file may have changed in an editor).</summary>
  public string ReloadSource()
  {
    if (Path == null)
      throw new InvalidOperationException($"Scene '{Name}' is built in and has no source file.");
    try
    {
      Source = File.ReadAllText(Path);
    }
    catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
    {
      throw new SceneEvaluationException($"{Path}: cannot read the script ({ex.Message}).", ex);
    }
    return Source;
  }

  public override string ToString() => Name;
}
