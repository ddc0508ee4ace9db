namespace GrCis.Interactive;

/// <summary>Where a scene in the list comes from.</summary>
public enum SceneEntryKind
{
  /// <summary>Compiled into the program (the classic GrCis scenes).</summary>
  BuiltIn,

  /// <summary>A C# scene script on disk.</summary>
  Script,
}
