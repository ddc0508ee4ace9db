using System;
using System.IO;

namespace GrCis.Cli.Tests;

/// <summary>Paths in the repository the tests run from (found by walking up to GrCis.sln).</summary>
internal static class RepoPaths
{
  static readonly Lazy<string> root = new(() =>
  {
    for (DirectoryInfo? d = new(AppContext.BaseDirectory); d != null; d = d.Parent)
      if (File.Exists(Path.Combine(d.FullName, "GrCis.sln")) && Directory.Exists(Path.Combine(d.FullName, "scripts")))
        return d.FullName;
    throw new InvalidOperationException($"repository root (GrCis.sln with scripts/) not found above {AppContext.BaseDirectory}");
  });

  public static string Root => root.Value;

  /// <summary>The scene scripts folder, scripts/ at the repository root.</summary>
  public static string Scripts => Path.Combine(Root, "scripts");

  public static string Script(string name) => Path.Combine(Scripts, name);
}
