using System;
using System.Collections.Generic;
using System.IO;

namespace Utilities;

/// <summary>
/// Finds a data file (mesh, texture, any file a script reads) named the way GrCis scripts named them on
/// Windows: with <c>\</c> separators, in any letter case, relative to the current folder, to the script's
/// own folder, or to GrCis's working folder — the project's <c>bin/Debug</c>, so that
/// <c>..\..\..\data\rtscenes\scene.yaml</c> meant the repository's <c>data/rtscenes</c>. The script host
/// sets <see cref="ScriptDirectory"/> on the thread while a script runs (kept in the thread's
/// <see cref="Rendering.Execution.WorkerContext"/>, so a render's workers inherit it).
/// </summary>
public static class DataFiles
{
  /// <summary>
  /// How many folders above the script's folder (and the current folder) a path written for GrCis's working
  /// folder is looked for, beyond the levels its leading <c>..</c> segments climb.
  /// </summary>
  public const int SearchLevels = 4;

  /// <summary>Folder of the script running on this thread (null outside scripts).</summary>
  public static string? ScriptDirectory => Rendering.Execution.WorkerContext.Current.ScriptDirectory;

  /// <summary>While the scope lives, relative paths on this thread are also looked up in <paramref name="directory"/>.</summary>
  public static Scope UseScriptDirectory(string? directory)
  {
    Rendering.Execution.WorkerContext c = Rendering.Execution.WorkerContext.Current;
    string? previous = c.ScriptDirectory;
    c.ScriptDirectory = directory;
    return new Scope(c, previous);
  }

  /// <summary>
  /// <see cref="Resolve"/> for a path that may be null or empty (returned as it is, so the caller's own error
  /// stays). The script host routes the paths scripts and modules pass to <c>File.ReadAllText</c>,
  /// <c>new StreamReader(path)</c> and the like through it.
  /// </summary>
  public static string? ResolveOrKeep(string? path) => string.IsNullOrEmpty(path) ? path : Resolve(path);

  /// <summary>
  /// The existing file <paramref name="path"/> names, tried in this order: as written; with <c>\</c> read as a
  /// separator; when relative, beside the running script. Then, where this file system tells letter case
  /// apart, the same with each folder and file name matched in any case (when exactly one entry matches).
  /// Then, for a relative path, as GrCis's working folder <c>&lt;project&gt;/bin/Debug</c> read it: without its
  /// leading <c>..</c> and <c>.</c> segments, under the script's folder or one of its parents (nearest first,
  /// at most <see cref="SearchLevels"/> plus the number of <c>..</c> segments up), then likewise under the
  /// current folder; a path that climbs at least two folders (out of <c>bin/Debug</c>) is also looked for in
  /// the folders beside the script's folder and beside those above it (the project folders of a GrCis fork;
  /// nearest first, used only when exactly one of them has the file). When nothing exists, <paramref name="path"/> itself, so the caller's "not found" names
  /// what the script wrote.
  /// </summary>
  public static string Resolve(string path)
  {
    ArgumentException.ThrowIfNullOrEmpty(path);
    string found = Find(path);
    if (Rendering.Execution.WorkerContext.Current.DataFileLog is ICollection<string> log && File.Exists(found))
      log.Add(Path.GetFullPath(found));
    return found;
  }

  /// <summary>
  /// While the scope lives, every existing file <see cref="Resolve"/> finds on this thread (the script's own reads, its
  /// textures and meshes) is added to <paramref name="log"/> as a full path: a front end that re-renders when the scene's
  /// files change (<c>grcis render --watch</c>) learns which files those are.
  /// </summary>
  public static LogScope LogReads(ICollection<string> log)
  {
    ArgumentNullException.ThrowIfNull(log);
    Rendering.Execution.WorkerContext c = Rendering.Execution.WorkerContext.Current;
    ICollection<string>? previous = c.DataFileLog;
    c.DataFileLog = log;
    return new LogScope(c, previous);
  }

  static string Find(string path)
  {
    if (File.Exists(path))
      return path;
    string portable = Path.DirectorySeparatorChar == '\\' ? path : path.Replace('\\', '/');
    if (File.Exists(portable))
      return portable;
    string? script = ScriptDirectory;
    bool relative = !Path.IsPathRooted(portable);
    if (script != null && relative)
    {
      string beside = Path.Combine(script, portable);
      if (File.Exists(beside))
        return beside;
    }

    if (relative)
    {
      string current = Directory.GetCurrentDirectory();
      if (FindIgnoringCase(current, portable) is string inCurrent)
        return inCurrent;
      if (script != null && FindIgnoringCase(script, portable) is string inScript)
        return inScript;
      if (FindInWorkingFolderForm(script, current, portable) is string found)
        return found;
    }
    else if (FindIgnoringCase(Path.GetPathRoot(portable)!, portable[Path.GetPathRoot(portable)!.Length..]) is string rooted)
      return rooted;
    return path;
  }

  /// <summary>The relative path without its leading <c>..</c>, under each base folder or its parents, nearest first.</summary>
  static string? FindInWorkingFolderForm(string? script, string current, string relative)
  {
    List<string> segments = Segments(relative);
    int up = 0;
    while (up < segments.Count && (segments[up] == ".." || segments[up] == "."))
      up++;
    if (up == segments.Count)
      return null;
    string rest = string.Join('/', segments.GetRange(up, segments.Count - up));
    int levels = SearchLevels + up;
    foreach (string? start in new[] { script, current })
    {
      if (start == null)
        continue;
      DirectoryInfo? dir = new(Path.GetFullPath(start));
      for (int level = 0; level <= levels && dir != null; level++, dir = dir.Parent)
        if (FindIgnoringCase(dir.FullName, rest) is string found)
          return found;
    }

    // "..\..\x" left bin/Debug for its project folder, a sibling of the script's folder or of a folder above it
    // (a script in data/rtscenes run by 048rtmontecarlo-script): the one project folder that has the file.
    if (up < 2 || script == null)
      return null;
    DirectoryInfo? above = new DirectoryInfo(Path.GetFullPath(script)).Parent;
    for (int level = 1; level <= levels && above != null; level++, above = above.Parent)
    {
      string? only = null;
      foreach (string project in Subfolders(above.FullName))
      {
        if (FindIgnoringCase(project, rest) is not string found)
          continue;
        if (only != null)
          return null;   // several projects have it: which one ran the script is unknown
        only = found;
      }
      if (only != null)
        return only;
    }
    return null;
  }

  static string[] Subfolders(string directory)
  {
    try
    {
      return Directory.GetDirectories(directory);
    }
    catch (Exception e) when (e is IOException or UnauthorizedAccessException)
    {
      return Array.Empty<string>();
    }
  }

  /// <summary>
  /// The file <paramref name="relative"/> names under <paramref name="baseDirectory"/>, each name matched exactly
  /// or, failing that, in any letter case when exactly one entry of its folder matches; null when none or ambiguous.
  /// </summary>
  static string? FindIgnoringCase(string baseDirectory, string relative)
  {
    List<string> segments = Segments(relative);
    if (segments.Count == 0)
      return null;
    string dir = baseDirectory;
    for (int i = 0; i < segments.Count; i++)
    {
      string name = segments[i];
      bool last = i == segments.Count - 1;
      if (name == "." && !last)
        continue;
      if (name == ".." && !last)
      {
        string? parent = Path.GetDirectoryName(Path.TrimEndingDirectorySeparator(Path.GetFullPath(dir)));
        if (parent == null)
          return null;
        dir = parent;
        continue;
      }
      string exact = Path.Combine(dir, name);
      if (last ? File.Exists(exact) : Directory.Exists(exact))
      {
        dir = exact;
        continue;
      }
      string? match = SingleMatch(dir, name, last);
      if (match == null)
        return null;
      dir = match;
    }
    return dir;
  }

  /// <summary>The one file (or folder) of <paramref name="dir"/> whose name equals <paramref name="name"/> ignoring case.</summary>
  static string? SingleMatch(string dir, string name, bool file)
  {
    string? match = null;
    try
    {
      IEnumerable<string> entries = file ? Directory.EnumerateFiles(dir) : Directory.EnumerateDirectories(dir);
      foreach (string entry in entries)
      {
        if (!string.Equals(Path.GetFileName(entry), name, StringComparison.OrdinalIgnoreCase))
          continue;
        if (match != null)
          return null;   // "Scene.yaml" and "scene.yaml": which one the student meant is unknown
        match = entry;
      }
    }
    catch (Exception e) when (e is IOException or UnauthorizedAccessException)
    {
      return null;
    }
    return match;
  }

  static List<string> Segments(string path)
  {
    var segments = new List<string>();
    foreach (string s in path.Split(new[] { '/', Path.DirectorySeparatorChar }, StringSplitOptions.RemoveEmptyEntries))
      segments.Add(s);
    return segments;
  }

  /// <summary>Restores the thread's previous script folder.</summary>
  public readonly struct Scope : IDisposable
  {
    readonly Rendering.Execution.WorkerContext? context;
    readonly string? previous;

    internal Scope(Rendering.Execution.WorkerContext context, string? previous)
    {
      this.context = context;
      this.previous = previous;
    }

    /// <summary>Gives the thread its previous script folder back.</summary>
    public void Dispose()
    {
      if (context != null)
        context.ScriptDirectory = previous;
    }
  }

  /// <summary>Restores the thread's previous read log (see <see cref="LogReads"/>).</summary>
  public readonly struct LogScope : IDisposable
  {
    readonly Rendering.Execution.WorkerContext? context;
    readonly ICollection<string>? previous;

    internal LogScope(Rendering.Execution.WorkerContext context, ICollection<string>? previous)
    {
      this.context = context;
      this.previous = previous;
    }

    /// <summary>Stops logging into this scope's log.</summary>
    public void Dispose()
    {
      if (context != null)
        context.DataFileLog = previous;
    }
  }
}
