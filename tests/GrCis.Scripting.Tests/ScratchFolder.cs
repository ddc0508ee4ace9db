using System;
using System.IO;

namespace GrCis.Scripting.Tests;

/// <summary>A temporary folder for scripts and modules a test writes; deleted with the test.</summary>
public sealed class ScratchFolder : IDisposable
{
  public ScratchFolder(string prefix) => Path = Directory.CreateTempSubdirectory(prefix).FullName;

  public string Path { get; }

  /// <summary>Writes <paramref name="text"/> to <paramref name="relative"/> (folders created); returns the full path.</summary>
  public string Write(string relative, string text)
  {
    string path = System.IO.Path.Combine(Path, relative);
    Directory.CreateDirectory(System.IO.Path.GetDirectoryName(path)!);
    File.WriteAllText(path, text);
    return path;
  }

  public void Dispose() => Directory.Delete(Path, recursive: true);
}
