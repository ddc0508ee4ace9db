using System;
using System.IO;

namespace GrCis.TestSupport;

/// <summary>
/// Points the compiled-script cache of a test process (<c>GRCIS_CACHE_DIR</c>) at a folder of its own, removed
/// when the process ends: <c>grcis</c> run in-process, and the <c>grcis</c> processes a test starts (they inherit
/// the environment), never write into the user's cache folder. Each test assembly that runs <c>grcis</c> calls
/// <see cref="Use"/> from a module initializer, before any test.
/// </summary>
public static class TestScriptCache
{
  /// <summary>The variable <c>grcis</c> reads (GrCis.Scripting.Caching.ScriptCache.DirectoryVariable).</summary>
  public const string DirectoryVariable = "GRCIS_CACHE_DIR";

  static readonly object sync = new();
  static string? folder;

  /// <summary>The test process's cache folder (set by <see cref="Use"/>).</summary>
  public static string Folder => folder ?? throw new InvalidOperationException("TestScriptCache.Use() was not called");

  public static void Use()
  {
    lock (sync)
    {
      if (folder != null)
        return;
      folder = Path.Combine(Path.GetTempPath(), $"grcis-test-cache-{Environment.ProcessId}-{Guid.NewGuid().ToString("N")[..12]}");
      Environment.SetEnvironmentVariable(DirectoryVariable, folder);
      string dir = folder;
      AppDomain.CurrentDomain.ProcessExit += (_, _) =>
      {
        try
        {
          if (Directory.Exists(dir))
            Directory.Delete(dir, recursive: true);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
        }
      };
    }
  }
}
