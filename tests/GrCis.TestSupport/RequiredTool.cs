using System;
using System.IO;
using Xunit;

namespace GrCis.TestSupport;

/// <summary>
/// The rule for tests that need a program a fresh machine lacks (GNU parallel, ffmpeg, chromium,
/// wine, …): when the program is missing the test is skipped with a message naming the Debian
/// package, unless <c>GRCIS_REQUIRE_TOOLS=1</c>, when it fails instead (<c>.ci/run</c> installs the
/// packages and sets the variable, so CI never skips silently).
/// </summary>
/// <remarks>Tests that call it are <c>[SkippableFact]</c> or <c>[SkippableTheory]</c>.</remarks>
public static class RequiredTool
{
  /// <summary>The environment variable that turns a skip into a failure.</summary>
  public const string RequireVariable = "GRCIS_REQUIRE_TOOLS";

  /// <summary>The full path of <paramref name="command"/> on PATH; skips or fails when it is not there.</summary>
  public static string Find(string command, string debianPackage) =>
    Find(command, debianPackage, Environment.GetEnvironmentVariable("PATH"), Required);

  /// <summary>The same rule for a shared library (found by the caller, e.g. with NativeLibrary.TryLoad): skips or fails when absent.</summary>
  public static void Library(string library, bool present, string debianPackage)
  {
    if (!present)
      throw Missing(library, debianPackage, Required);
  }

  /// <summary>
  /// The same rule for something else a test needs from outside the machine (a package fetched from a registry):
  /// the exception to throw, a skip with <paramref name="message"/>, or a failure when the tools are required.
  /// </summary>
  public static Exception Unavailable(string message) => Unavailable(message, Required);

  /// <summary>True when <c>GRCIS_REQUIRE_TOOLS=1</c>: a missing tool fails the test.</summary>
  public static bool Required => Environment.GetEnvironmentVariable(RequireVariable) == "1";

  /// <summary>The rule itself, with PATH and the require switch passed in (so it can be tested).</summary>
  public static string Find(string command, string debianPackage, string? path, bool required)
  {
    return OnPath(command, path) ?? throw Missing(command, debianPackage, required);
  }

  // What a missing tool or library gives: a skip naming its Debian package, or a failure when the tools are required.
  static Exception Missing(string what, string debianPackage, bool required)
  {
    string message = $"'{what}' is not installed: install the Debian package '{debianPackage}' (apt-get install -y {debianPackage}; .ci/run does)";
    return Unavailable(message, required);
  }

  static Exception Unavailable(string message, bool required) =>
    required ? new Xunit.Sdk.XunitException(message + $"; {RequireVariable}=1, so this fails instead of skipping") : new SkipException(message);

  /// <summary>The first executable file named <paramref name="command"/> in the PATH list, or null.</summary>
  public static string? OnPath(string command, string? path)
  {
    if (string.IsNullOrEmpty(path))
      return null;
    foreach (string dir in path.Split(Path.PathSeparator, StringSplitOptions.RemoveEmptyEntries))
    {
      string candidate = Path.Combine(dir, command);
      if (File.Exists(candidate) && IsExecutable(candidate))
        return candidate;
      if (OperatingSystem.IsWindows() && File.Exists(candidate + ".exe"))
        return candidate + ".exe";
    }
    return null;
  }

  static bool IsExecutable(string file) =>
    OperatingSystem.IsWindows() ||
    (File.GetUnixFileMode(file) & (UnixFileMode.UserExecute | UnixFileMode.GroupExecute | UnixFileMode.OtherExecute)) != 0;
}
