using System;
using System.Collections.Generic;
using System.IO;

namespace GrCis.Studio;

/// <summary>
/// The files the studio may read and write: the scripts given on the command line and the files inside the
/// folders given there, nothing else. A path is compared after it is made absolute and normalised, so
/// <c>..</c> segments cannot leave a folder; links inside a folder are followed to their target, which must
/// be allowed too.
/// </summary>
public sealed class AllowedFiles
{
  readonly HashSet<string> files;
  readonly List<string> folders = new();

  public AllowedFiles(IEnumerable<string> paths)
  {
    files = new HashSet<string>(Comparer);
    foreach (string p in paths)
    {
      string full = Path.GetFullPath(p);
      if (Directory.Exists(full))
        folders.Add(Path.TrimEndingDirectorySeparator(full) + Path.DirectorySeparatorChar);
      else
        files.Add(full);
    }
  }

  static StringComparer Comparer => OperatingSystem.IsWindows() ? StringComparer.OrdinalIgnoreCase : StringComparer.Ordinal;

  static StringComparison Comparison => OperatingSystem.IsWindows() ? StringComparison.OrdinalIgnoreCase : StringComparison.Ordinal;

  /// <summary>
  /// The scene scripts (<c>*.cs</c>) the studio may open: the given files and every script in the given folders
  /// and their subfolders (at most <paramref name="limit"/>), as full paths in a stable order.
  /// </summary>
  public IReadOnlyList<string> Scripts(int limit = 2000)
  {
    var found = new SortedSet<string>(Comparer);
    foreach (string file in files)
      if (file.EndsWith(".cs", Comparison) && File.Exists(file))
        found.Add(file);
    var options = new EnumerationOptions { RecurseSubdirectories = true, IgnoreInaccessible = true, MaxRecursionDepth = 8 };
    foreach (string folder in folders)
      foreach (string file in Directory.EnumerateFiles(folder, "*.cs", options))
      {
        if (found.Count >= limit)
          return [.. found];
        if (Allows(file))
          found.Add(Path.GetFullPath(file));
      }
    return [.. found];
  }

  /// <summary>True when <paramref name="path"/> is a given file or lies inside a given folder (and so does its link target).</summary>
  public bool Allows(string path)
  {
    if (string.IsNullOrWhiteSpace(path) || path.Contains('\0'))
      return false;
    string full;
    try
    {
      full = Path.GetFullPath(path);
    }
    catch (Exception e) when (e is ArgumentException or NotSupportedException or PathTooLongException)
    {
      return false;
    }
    if (!Listed(full))
      return false;
    FileSystemInfo? target = File.Exists(full) ? new FileInfo(full).ResolveLinkTarget(returnFinalTarget: true) : null;
    return target == null || Listed(Path.GetFullPath(target.FullName));
  }

  bool Listed(string full)
  {
    if (files.Contains(full))
      return true;
    foreach (string folder in folders)
      if (full.StartsWith(folder, Comparison))
        return true;
    return false;
  }
}
