using System;
using System.IO;

namespace Utilities;

/// <summary>
/// Finds a data file (mesh, texture) a scene script names the way GrCis scripts did: written on Windows
/// with <c>\</c> separators, relative to the current folder or to the script's own folder. The script
/// host sets <see cref="ScriptDirectory"/> on the thread while a script runs.
/// </summary>
public static class DataFiles
{
  [ThreadStatic]
  static string? scriptDirectory;

  /// <summary>Folder of the script running on this thread (null outside scripts).</summary>
  public static string? ScriptDirectory => scriptDirectory;

  /// <summary>While the scope lives, relative paths on this thread are also looked up in <paramref name="directory"/>.</summary>
  public static Scope UseScriptDirectory(string? directory)
  {
    string? previous = scriptDirectory;
    scriptDirectory = directory;
    return new Scope(previous);
  }

  /// <summary>
  /// <paramref name="path"/> if it exists; else the same with <c>\</c> read as a separator; else either,
  /// when relative, under <see cref="ScriptDirectory"/>. When nothing exists, <paramref name="path"/>
  /// itself, so the caller's "not found" names what the script wrote.
  /// </summary>
  public static string Resolve(string path)
  {
    ArgumentException.ThrowIfNullOrEmpty(path);
    if (File.Exists(path))
      return path;
    string portable = Path.DirectorySeparatorChar == '\\' ? path : path.Replace('\\', '/');
    if (File.Exists(portable))
      return portable;
    if (scriptDirectory != null && !Path.IsPathRooted(portable))
    {
      string beside = Path.Combine(scriptDirectory, portable);
      if (File.Exists(beside))
        return beside;
    }
    return path;
  }

  /// <summary>Restores the thread's previous script folder.</summary>
  public readonly struct Scope : IDisposable
  {
    readonly string? previous;

    internal Scope(string? previous) => this.previous = previous;

    public void Dispose() => scriptDirectory = previous;
  }
}
