using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;

namespace GrCis.Cli.Scaffolding;

/// <summary>
/// Writes a set of new files into a folder, all or none: an existing file is never replaced (refused before
/// anything is written, and a file appearing meanwhile stops the write), and a failure removes what this
/// write created.
/// </summary>
internal static class SceneFolderWriter
{
  /// <summary>Writes <paramref name="files"/> below <paramref name="folder"/>; returns their full paths.</summary>
  /// <exception cref="CliFailure">A file exists already, or writing failed (then nothing is left behind).</exception>
  public static IReadOnlyList<string> Write(string folder, IReadOnlyList<(string Path, string Text)> files)
  {
    string[] targets = files.Select(f => Path.Combine(folder, f.Path.Replace('/', Path.DirectorySeparatorChar))).ToArray();
    string[] existing = targets.Where(t => File.Exists(t) || Directory.Exists(t)).ToArray();
    if (existing.Length > 0)
      throw new CliFailure($"{folder}: already has {string.Join(", ", existing.Select(e => Path.GetRelativePath(folder, e)))}; " +
                           "nothing written (grcis init never replaces a file: choose another folder or remove them)");

    var createdDirs = new List<string>();
    var createdFiles = new List<string>();
    try
    {
      for (int i = 0; i < files.Count; i++)
      {
        CreateDirectories(Path.GetDirectoryName(targets[i])!, createdDirs);
        // A temporary file in the same folder, then a rename that fails if the name was taken meanwhile.
        string temp = Path.Combine(Path.GetDirectoryName(targets[i])!, "." + Path.GetFileName(targets[i]) + ".tmp-" + Guid.NewGuid().ToString("N")[..8]);
        try
        {
          // Created new: a file or link of that name is never written through.
          using (var w = new StreamWriter(new FileStream(temp, FileMode.CreateNew, FileAccess.Write, FileShare.None), new UTF8Encoding(false)))
            w.Write(files[i].Text);
          File.Move(temp, targets[i], overwrite: false);
        }
        finally
        {
          File.Delete(temp);
        }
        createdFiles.Add(targets[i]);
      }
    }
    catch (Exception e) when (e is IOException or UnauthorizedAccessException)
    {
      foreach (string f in createdFiles)
        TryDelete(() => File.Delete(f));
      for (int i = createdDirs.Count - 1; i >= 0; i--)
        TryDelete(() => Directory.Delete(createdDirs[i]));
      throw new CliFailure($"{folder}: could not write the scene folder ({e.Message}); nothing written", e);
    }
    return targets;
  }

  /// <summary>Creates <paramref name="dir"/> and its missing parents, recording each created one (outermost first).</summary>
  static void CreateDirectories(string dir, List<string> created)
  {
    var missing = new Stack<string>();
    for (string? d = dir; !string.IsNullOrEmpty(d) && !Directory.Exists(d); d = Path.GetDirectoryName(d))
      missing.Push(d);
    while (missing.Count > 0)
    {
      string d = missing.Pop();
      Directory.CreateDirectory(d);
      created.Add(d);
    }
  }

  static void TryDelete(Action delete)
  {
    try
    {
      delete();
    }
    catch (Exception e) when (e is IOException or UnauthorizedAccessException)
    {
      // Best effort: the error being reported is the first one.
    }
  }
}
