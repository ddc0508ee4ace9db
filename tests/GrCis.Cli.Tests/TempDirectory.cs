using System;
using System.IO;

namespace GrCis.Cli.Tests;

/// <summary>A fresh empty directory, removed (with anything left in it) on dispose.</summary>
internal sealed class TempDirectory : IDisposable
{
  public TempDirectory()
  {
    Path = System.IO.Path.Combine(System.IO.Path.GetTempPath(), "grcis-cli-tests-" + Guid.NewGuid().ToString("N")[..12]);
    Directory.CreateDirectory(Path);
  }

  public string Path { get; }

  public string File(string name) => System.IO.Path.Combine(Path, name);

  /// <summary>Every file below the directory (to prove nothing, not even a temporary file, was left).</summary>
  public string[] AllFiles() => Directory.GetFiles(Path, "*", SearchOption.AllDirectories);

  public void Dispose()
  {
    if (!OperatingSystem.IsWindows())
    {
      // Restore permissions a test removed, so the directory can be deleted.
      foreach (string d in Directory.GetDirectories(Path, "*", SearchOption.AllDirectories))
        System.IO.File.SetUnixFileMode(d, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute);
    }
    try
    {
      Directory.Delete(Path, recursive: true);
    }
    catch (IOException)
    {
    }
  }
}
