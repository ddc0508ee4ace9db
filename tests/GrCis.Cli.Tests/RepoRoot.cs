using System;
using System.IO;

namespace GrCis.Cli.Tests;

/// <summary>The repository's root folder (the one holding GrCis.sln), found upwards from the test binaries.</summary>
internal static class RepoRoot
{
  public static string Path { get; } = Find();

  static string Find()
  {
    for (string? dir = AppContext.BaseDirectory; dir != null; dir = Directory.GetParent(dir)?.FullName)
      if (File.Exists(System.IO.Path.Combine(dir, "GrCis.sln")))
        return dir;
    throw new InvalidOperationException($"GrCis.sln not found above {AppContext.BaseDirectory}");
  }
}
