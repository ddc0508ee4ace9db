using System;
using System.IO;

namespace GrCis.Rendering.Tests;

/// <summary>
/// The workplace's read-only shared folder (reference renders, meshes), which is never copied into
/// the repository: $GRCIS_SHARED, else a "shared" folder beside any directory above the test
/// binaries (the checkout's own ../shared), else /work/shared where this project's machines keep it.
/// </summary>
internal static class SharedFolder
{
  static readonly Lazy<string> path = new(Find);

  public static string Path => path.Value;

  public static string Combine(params string[] parts) => System.IO.Path.Combine(Path, System.IO.Path.Combine(parts));

  static string Find()
  {
    string? env = Environment.GetEnvironmentVariable("GRCIS_SHARED");
    if (!string.IsNullOrEmpty(env))
    {
      if (Directory.Exists(System.IO.Path.Combine(env, "refs")))
        return env;
      throw new DirectoryNotFoundException($"GRCIS_SHARED is '{env}', which has no refs/ folder.");
    }
    for (DirectoryInfo? d = new(AppContext.BaseDirectory); d != null; d = d.Parent)
    {
      string candidate = System.IO.Path.Combine(d.FullName, "shared");
      if (Directory.Exists(System.IO.Path.Combine(candidate, "refs", "grcis")))
        return candidate;
    }
    const string machine = "/work/shared";
    if (Directory.Exists(System.IO.Path.Combine(machine, "refs", "grcis")))
      return machine;
    throw new DirectoryNotFoundException(
      $"The shared folder (refs/grcis, data/meshes) was not found above {AppContext.BaseDirectory} nor at {machine}; " +
      "set GRCIS_SHARED to it.");
  }
}
