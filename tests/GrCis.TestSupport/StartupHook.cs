using System;
using System.IO;
using System.Linq;

/// <summary>
/// Loaded into a <c>grcis</c> process that a test starts with <c>DOTNET_STARTUP_HOOKS</c> naming this assembly
/// (GrCis.Cli.Tests' <c>ScriptCacheTests</c>): when the process exits, the names of the assemblies it loaded are written to the
/// file named by <see cref="FileVariable"/>. Uses nothing but the base library, so it loads nothing of its own.
/// </summary>
public static class StartupHook
{
  public const string FileVariable = "GRCIS_TEST_LOADED_ASSEMBLIES";

  public static void Initialize()
  {
    string? file = Environment.GetEnvironmentVariable(FileVariable);
    if (string.IsNullOrEmpty(file))
      return;
    AppDomain.CurrentDomain.ProcessExit += (_, _) =>
      File.WriteAllLines(file, AppDomain.CurrentDomain.GetAssemblies().Select(a => a.GetName().Name ?? "").Order(StringComparer.Ordinal));
  }
}
