using System;
using System.Collections.Generic;
using System.IO;
using Rendering;

using GrCis.Hosting;
using GrCis.Scripting.Caching;

namespace GrCis.Cli.SceneSources;

/// <summary>
/// Turns the scene argument of <c>grcis render</c> into a <see cref="ISceneSource"/>:
/// nothing → the default scene; a path ending in <c>.cs</c> → a scene script; anything else → a
/// built-in scene by name (case, spaces and punctuation ignored); a folder or another file is an
/// error that says so.
/// </summary>
public sealed class SceneResolver
{
  readonly string workingDirectory;

  public SceneResolver(string workingDirectory) => this.workingDirectory = workingDirectory;

  /// <summary>Names of the built-in scenes, in GrCis's order.</summary>
  public static IReadOnlyList<string> BuiltInNames => Scenes.Names;

  /// <summary>The scene rendered when none is given.</summary>
  public static string DefaultSceneName => Scenes.DefaultSceneName;

  /// <exception cref="UsageException">Unknown scene name (with close matches), a folder or non-script file, or a script that does not exist.</exception>
  public ISceneSource Resolve(string? spec) => Resolve(spec, null, Array.Empty<string>());

  /// <summary>As <see cref="Resolve(string?)"/>; a script gets <paramref name="param"/> and the module folders.</summary>
  /// <param name="diskCache">Where a script's compiled code is kept between runs (null: compiled afresh).</param>
  /// <param name="beforeCompile">Called before the script or a module is compiled (<see cref="GrCis.Scripting.ScriptHost.BeforeCompile"/>).</param>
  /// <exception cref="UsageException">Unknown scene, missing script or module folder, or script options for a built-in scene.</exception>
  public ISceneSource Resolve(string? spec, string? param, IReadOnlyList<string> modules, ScriptCache? diskCache = null,
                              Action? beforeCompile = null)
  {
    if (!string.IsNullOrWhiteSpace(spec) && !spec.StartsWith('-') && IsScriptPath(spec))
      return ResolveScript(spec, param, modules, diskCache, beforeCompile);
    if (modules.Count > 0)
      throw new UsageException("--module works only with a scene script (*.cs)");
    return ResolveBuiltIn(spec, param);
  }

  ISceneSource ResolveBuiltIn(string? spec, string? param)
  {
    if (string.IsNullOrWhiteSpace(spec))
      return new BuiltInSceneSource(DefaultSceneName, param);
    if (spec.StartsWith('-'))
      throw new UsageException($"unknown option '{spec}' (see 'grcis render --help')");

    string? name = Scenes.CanonicalName(spec);
    if (name != null)
      return new BuiltInSceneSource(name, param);
    NotASceneFile(spec);

    IReadOnlyList<string> close = NameSuggestions.Closest(spec, BuiltInNames);
    string hint = close.Count > 0
      ? $"did you mean {string.Join(" or ", Quote(close))}?"
      : "run 'grcis list' to see the built-in scenes";
    throw new UsageException($"unknown scene '{spec}'; {hint}");
  }

  /// <summary>A folder or a file that is no script is named as such (not as an unknown scene), with what is expected.</summary>
  void NotASceneFile(string spec)
  {
    string path;
    try
    {
      path = Path.GetFullPath(spec, workingDirectory);
    }
    catch (Exception e) when (e is ArgumentException or NotSupportedException or PathTooLongException)
    {
      return;
    }
    const string expected = "give a built-in scene name (see 'grcis list') or a scene script (*.cs)";
    if (Directory.Exists(path))
    {
      string[] scripts = Directory.GetFiles(path, "*.cs");
      Array.Sort(scripts, StringComparer.Ordinal);
      string example = scripts.Length > 0 ? $", e.g. '{Path.Combine(spec, Path.GetFileName(scripts[0]))}'" : "";
      throw new UsageException($"'{spec}' is a folder, not a scene; {expected}{example} (a folder of classes is a --module)");
    }
    if (File.Exists(path))
      throw new UsageException($"'{spec}' is a file but not a scene script; {expected}");
  }

  /// <summary>The target of a link that leads nowhere (.NET's File.Exists is true for the link itself), else null.</summary>
  static string? BrokenLink(string path)
  {
    var file = new FileInfo(path);
    if (file.LinkTarget is not string target)
      return null;
    try
    {
      return file.ResolveLinkTarget(returnFinalTarget: true) is { Exists: true } ? null : target;
    }
    catch (IOException)
    {
      return target;   // a loop of links
    }
  }

  static bool IsScriptPath(string spec) => spec.EndsWith(".cs", StringComparison.OrdinalIgnoreCase);

  ISceneSource ResolveScript(string spec, string? param, IReadOnlyList<string> modules, ScriptCache? diskCache, Action? beforeCompile)
  {
    string path = Path.GetFullPath(spec, workingDirectory);
    if (Directory.Exists(path))
      throw new UsageException($"scene script '{spec}' is a directory; give a .cs file (a folder of classes is a --module)");
    if (!File.Exists(path))
      throw new UsageException($"scene script '{spec}' not found (looked for '{path}')");
    if (BrokenLink(path) is string target)
      throw new UsageException($"scene script '{spec}' not found: it is a link to '{target}', which does not exist");
    var dirs = new List<string>(modules.Count);
    foreach (string m in modules)
    {
      string dir = Path.GetFullPath(m, workingDirectory);
      if (!Directory.Exists(dir))
        throw new UsageException($"module folder '{m}' not found (looked for '{dir}')");
      dirs.Add(dir);
    }
    return new ScriptSceneSource(path, param, dirs, diskCache, beforeCompile);
  }

  static IEnumerable<string> Quote(IEnumerable<string> names)
  {
    foreach (string n in names)
      yield return $"'{n}'";
  }
}
