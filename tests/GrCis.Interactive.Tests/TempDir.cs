using System;
using System.IO;

namespace GrCis.Interactive.Tests;

/// <summary>A temporary folder removed after the test.</summary>
internal sealed class TempDir : IDisposable
{
  public string Path { get; } = Directory.CreateTempSubdirectory("grcis-interactive-").FullName;

  public string File(string name) => System.IO.Path.Combine(Path, name);

  public void Dispose()
  {
    try { Directory.Delete(Path, recursive: true); } catch (IOException) { }
  }
}
