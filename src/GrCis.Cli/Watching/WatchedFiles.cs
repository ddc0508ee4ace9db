using System;
using System.Collections.Generic;
using System.IO;

namespace GrCis.Cli.Watching;

/// <summary>
/// The files a <c>--watch</c> session re-renders for: single files (the script, the data files its scene read) and
/// folders of module sources (every <c>*.cs</c> below them, build output left out). One watcher per folder; the
/// folder is watched rather than the file, so an editor that saves by writing a new file and renaming it is seen too.
/// </summary>
internal sealed class WatchedFiles : IDisposable
{
  static readonly StringComparer PathComparer =
    OperatingSystem.IsWindows() || OperatingSystem.IsMacOS() ? StringComparer.OrdinalIgnoreCase : StringComparer.Ordinal;

  readonly object sync = new();
  readonly HashSet<string> files = new(PathComparer);
  readonly List<string> trees = new();
  readonly Dictionary<string, FileSystemWatcher> watchers = new(PathComparer);
  readonly Action<string> changed;

  /// <param name="changed">Called (on a thread pool thread) with the path of each watched file that changed.</param>
  public WatchedFiles(Action<string> changed) => this.changed = changed;

  /// <summary>How many single files are watched (module folders not counted).</summary>
  public int FileCount
  {
    get
    {
      lock (sync)
        return files.Count;
    }
  }

  /// <summary>Watches one file (full path); a file already watched is ignored.</summary>
  public void AddFile(string path)
  {
    string full = Path.GetFullPath(path);
    string? dir = Path.GetDirectoryName(full);
    if (dir == null || !Directory.Exists(dir))
      return;
    lock (sync)
      if (files.Add(full))
        Watch(dir, recursive: false);
  }

  /// <summary>Watches every <c>*.cs</c> file below a module folder, files created later too.</summary>
  public void AddModuleFolder(string directory)
  {
    string full = Path.TrimEndingDirectorySeparator(Path.GetFullPath(directory));
    if (!Directory.Exists(full))
      return;
    lock (sync)
      if (!trees.Exists(t => PathComparer.Equals(t, full)))
      {
        trees.Add(full);
        Watch(full, recursive: true);
      }
  }

  void Watch(string dir, bool recursive)
  {
    string key = (recursive ? "r:" : "f:") + dir;
    if (watchers.ContainsKey(key))
      return;
    var w = new FileSystemWatcher(dir)
    {
      IncludeSubdirectories = recursive,
      NotifyFilter = NotifyFilters.FileName | NotifyFilters.LastWrite | NotifyFilters.Size | NotifyFilters.CreationTime,
    };
    w.Changed += OnEvent;
    w.Created += OnEvent;
    w.Deleted += OnEvent;
    w.Renamed += (_, e) =>
    {
      if (Matches(e.OldFullPath))
        changed(e.OldFullPath);
      else if (Matches(e.FullPath))
        changed(e.FullPath);
    };
    // Too many events at once (the watcher's buffer overflowed): something may have changed.
    w.Error += (_, _) => changed(dir);
    w.EnableRaisingEvents = true;
    watchers[key] = w;
  }

  void OnEvent(object sender, FileSystemEventArgs e)
  {
    if (Matches(e.FullPath))
      changed(e.FullPath);
  }

  bool Matches(string path)
  {
    lock (sync)
    {
      if (files.Contains(path))
        return true;
      if (!path.EndsWith(".cs", StringComparison.OrdinalIgnoreCase))
        return false;
      foreach (string tree in trees)
        if (path.StartsWith(tree + Path.DirectorySeparatorChar, PathComparer == StringComparer.Ordinal ? StringComparison.Ordinal : StringComparison.OrdinalIgnoreCase) &&
            !IsBuildOutput(path[(tree.Length + 1)..]))
          return true;
      return false;
    }
  }

  /// <summary>A module's <c>bin/</c> and <c>obj/</c> are not part of it (an IDE build writes .cs files there).</summary>
  static bool IsBuildOutput(string relative)
  {
    foreach (string segment in relative.Split(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar))
      if (segment.Equals("bin", StringComparison.OrdinalIgnoreCase) || segment.Equals("obj", StringComparison.OrdinalIgnoreCase))
        return true;
    return false;
  }

  public void Dispose()
  {
    lock (sync)
    {
      foreach (FileSystemWatcher w in watchers.Values)
        w.Dispose();
      watchers.Clear();
    }
  }
}
