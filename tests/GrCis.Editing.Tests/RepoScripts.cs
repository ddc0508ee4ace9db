using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace GrCis.Editing.Tests;

/// <summary>The scene scripts students start from: every script of scripts/ and the template's scene script.</summary>
internal static class RepoScripts
{
  static readonly Lazy<string> root = new(() =>
  {
    for (DirectoryInfo? d = new(AppContext.BaseDirectory); d != null; d = d.Parent)
      if (File.Exists(Path.Combine(d.FullName, "GrCis.sln")) && Directory.Exists(Path.Combine(d.FullName, "scripts")))
        return d.FullName;
    throw new InvalidOperationException($"repository root (GrCis.sln with scripts/) not found above {AppContext.BaseDirectory}");
  });

  /// <summary>Full paths, in a fixed order.</summary>
  public static IReadOnlyList<string> All =>
    Directory.GetFiles(Path.Combine(root.Value, "scripts"), "*.cs").Order(StringComparer.Ordinal)
      .Append(Path.Combine(root.Value, "templates", "grcis-scene", "Scene.cs")).ToList();
}
