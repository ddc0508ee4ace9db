using System;
using System.Collections.Generic;
using System.IO;

namespace GrCis.Studio;

/// <summary>
/// The files the studio may list, read and write: the scripts given on the command line and the files inside the
/// folders given there, nothing else. A path is made absolute and normalised (so <c>..</c> cannot leave a folder) and
/// then resolved to its real path, every link on the way followed (the file's own and any folder's above it): both
/// must lie inside a given folder, so a link that leads out of the folders is neither listed, read nor written.
/// Endpoints read and write the real path (<see cref="Resolve"/>), never the text of the request.
/// </summary>
public sealed class AllowedFiles
{
  /// <summary>Links followed in one path before it is refused (a loop, or a maze).</summary>
  const int MaxLinks = 40;

  readonly HashSet<string> files;
  readonly List<string> folders = new();

  public AllowedFiles(IEnumerable<string> paths)
  {
    files = new HashSet<string>(Comparer);
    foreach (string p in paths)
    {
      string full = Path.GetFullPath(p);
      if (Directory.Exists(full))
      {
        // A folder given through a link is the folder it leads to: both spellings name it.
        folders.Add(AsFolder(full));
        if (TryRealPath(full) is string real)
          folders.Add(AsFolder(real));
      }
      else
        files.Add(full);
    }
  }

  static string AsFolder(string path) => Path.TrimEndingDirectorySeparator(path) + Path.DirectorySeparatorChar;

  static StringComparer Comparer => OperatingSystem.IsWindows() ? StringComparer.OrdinalIgnoreCase : StringComparer.Ordinal;

  static StringComparison Comparison => OperatingSystem.IsWindows() ? StringComparison.OrdinalIgnoreCase : StringComparison.Ordinal;

  /// <summary>
  /// The scene scripts (<c>*.cs</c>) the studio may open: the given files and every script in the given folders
  /// and their subfolders (at most <paramref name="limit"/>) that <see cref="Allows"/>, as full paths in a stable order.
  /// </summary>
  public IReadOnlyList<string> Scripts(int limit = 2000)
  {
    var found = new SortedSet<string>(Comparer);
    foreach (string file in files)
      if (file.EndsWith(".cs", Comparison) && File.Exists(file))
        found.Add(file);
    // Links are skipped (not followed into subfolders, not listed): a linked script is opened by its path, when its target is allowed.
    var options = new EnumerationOptions
    {
      RecurseSubdirectories = true,
      IgnoreInaccessible = true,
      MaxRecursionDepth = 8,
      AttributesToSkip = FileAttributes.Hidden | FileAttributes.System | FileAttributes.ReparsePoint,
    };
    foreach (string folder in folders)
    {
      if (!Directory.Exists(folder))
        continue;
      foreach (string file in Directory.EnumerateFiles(folder, "*.cs", options))
      {
        if (found.Count >= limit)
          return [.. found];
        if (Allows(file))
          found.Add(Path.GetFullPath(file));
      }
    }
    return [.. found];
  }

  /// <summary>True when <paramref name="path"/> is a given file, or it and its real path lie inside a given folder.</summary>
  public bool Allows(string path) => Resolve(path) != null;

  /// <summary>
  /// The real path to read or write for <paramref name="path"/> (every link followed), or null when the studio may not
  /// touch it: outside the given folders, lexically or through a link. A file given on the command line is allowed
  /// wherever it leads (the user named it).
  /// </summary>
  public string? Resolve(string path)
  {
    if (string.IsNullOrWhiteSpace(path) || path.Contains('\0'))
      return null;
    string full;
    try
    {
      full = Path.GetFullPath(path);
    }
    catch (Exception e) when (e is ArgumentException or NotSupportedException or PathTooLongException)
    {
      return null;
    }
    string? real = TryRealPath(full);
    if (real == null)
      return null;
    if (files.Contains(full))
      return real;
    return InFolder(full) && InFolder(real) ? real : null;
  }

  bool InFolder(string full)
  {
    foreach (string folder in folders)
      if (full.StartsWith(folder, Comparison))
        return true;
    return false;
  }

  static string? TryRealPath(string full)
  {
    try
    {
      return RealPath(full);
    }
    catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException)
    {
      return null;
    }
  }

  /// <summary>
  /// <paramref name="path"/> with every link on the way replaced by its target, from the root down (as the system's
  /// realpath, but a missing tail, such as a file about to be written, is kept as it is).
  /// </summary>
  /// <exception cref="IOException">More than <see cref="MaxLinks"/> links (a loop).</exception>
  public static string RealPath(string path)
  {
    string full = Path.GetFullPath(path);
    int links = 0;
    while (true)
    {
      string root = Path.GetPathRoot(full) ?? "";
      string[] parts = full[root.Length..].Split([Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar], StringSplitOptions.RemoveEmptyEntries);
      string current = root;
      string? restart = null;
      for (int i = 0; i < parts.Length && restart == null; i++)
      {
        string next = Path.Combine(current, parts[i]);
        string? target = new FileInfo(next).LinkTarget;
        if (target == null)
        {
          current = next;
          continue;
        }
        if (++links > MaxLinks)
          throw new IOException($"{path}: too many links on the way (a loop?)");
        // A relative target is relative to the link's folder; the rest of the path follows the target.
        restart = Path.GetFullPath(Path.Combine(Path.GetFullPath(target, current), Path.Combine(parts[(i + 1)..])));
      }
      if (restart == null)
        return current;
      full = restart;
    }
  }
}
