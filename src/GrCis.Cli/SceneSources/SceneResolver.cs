using System;
using System.Collections.Generic;
using System.IO;
using Rendering;

namespace GrCis.Cli.SceneSources;

/// <summary>
/// Turns the scene argument of <c>grcis render</c> into a <see cref="ISceneSource"/>:
/// nothing → the default scene; a path ending in <c>.cs</c> → a scene script; anything else → a
/// built-in scene by name (case, spaces and punctuation ignored).
/// </summary>
public sealed class SceneResolver
{
  readonly string workingDirectory;

  public SceneResolver(string workingDirectory) => this.workingDirectory = workingDirectory;

  /// <summary>Names of the built-in scenes, in GrCis's order.</summary>
  public static IReadOnlyList<string> BuiltInNames => Scenes.Names;

  /// <summary>The scene rendered when none is given.</summary>
  public static string DefaultSceneName => Scenes.DefaultSceneName;

  /// <exception cref="UsageException">Unknown scene name (with close matches) or a script that does not exist.</exception>
  public ISceneSource Resolve(string? spec)
  {
    if (string.IsNullOrWhiteSpace(spec))
      return new BuiltInSceneSource(DefaultSceneName);
    if (spec.StartsWith('-'))
      throw new UsageException($"unknown option '{spec}' (see 'grcis render --help')");
    if (IsScriptPath(spec))
      return ResolveScript(spec);

    string? name = Scenes.CanonicalName(spec);
    if (name != null)
      return new BuiltInSceneSource(name);

    IReadOnlyList<string> close = NameSuggestions.Closest(spec, BuiltInNames);
    string hint = close.Count > 0
      ? $"did you mean {string.Join(" or ", Quote(close))}?"
      : "run 'grcis list' to see the built-in scenes";
    throw new UsageException($"unknown scene '{spec}'; {hint}");
  }

  static bool IsScriptPath(string spec) => spec.EndsWith(".cs", StringComparison.OrdinalIgnoreCase);

  ISceneSource ResolveScript(string spec)
  {
    string path = Path.GetFullPath(spec, workingDirectory);
    if (!File.Exists(path))
      throw new UsageException($"scene script '{spec}' not found");
    // The scripting host plugs in here (GrCis.Scripting): compile the script, return its scene source.
    throw new UsageException($"scene scripts are not supported by this build yet: '{spec}'");
  }

  static IEnumerable<string> Quote(IEnumerable<string> names)
  {
    foreach (string n in names)
      yield return $"'{n}'";
  }
}
