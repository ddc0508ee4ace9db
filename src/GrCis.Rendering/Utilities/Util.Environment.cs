using System;
using System.IO;
using System.Reflection;
using System.Runtime.Versioning;
using System.Text;

namespace Utilities;

/// <summary>GrCis's helpers about the program and its files: versions, runtime, finding and reading files.</summary>
public static partial class Util
{
  /// <summary>Version text of the program (<see cref="SetVersion"/>); this library's version until a program sets its own.</summary>
  public static string ProgramVersion = AssemblyVersion(typeof(Util));

  /// <summary>The .NET this library was built for, e.g. ".NET 10.0".</summary>
  public static string TargetFramework = BuildTarget();

  /// <summary>The version of the runtime running now.</summary>
  public static string RunningFramework = Environment.Version.ToString();

  /// <summary>True on the Mono runtime.</summary>
  public static bool IsRunningOnMono => Type.GetType("Mono.Runtime") != null;

  /// <summary>Sets <see cref="ProgramVersion"/> from a revision text ("$Rev: 980 $" gives "Rev: 980") and refreshes the framework versions.</summary>
  public static string SetVersion(string revision)
  {
    GetFrameworkVersions(out TargetFramework, out RunningFramework);
    return ProgramVersion = revision.Replace('$', ' ').Trim();
  }

  /// <summary>Version of the assembly that defines <paramref name="t"/>.</summary>
  public static string AssemblyVersion(Type t) => t.Assembly.GetName().Version?.ToString() ?? "";

  /// <summary>The .NET this library was built for and the version of the running runtime.</summary>
  public static void GetFrameworkVersions(out string targetFramework, out string runningFramework)
  {
    targetFramework = BuildTarget();
    runningFramework = Environment.Version.ToString();
  }

  static string BuildTarget() =>
    typeof(Util).Assembly.GetCustomAttribute<TargetFrameworkAttribute>() is { } target
      ? target.FrameworkDisplayName ?? target.FrameworkName
      : "Unknown";

  /// <summary>
  /// Looks for <paramref name="fileName"/> in the current folder and up to three folders up, then (with a
  /// <paramref name="hint"/>) in the hint folder one to three levels up. The path found, or null.
  /// </summary>
  public static string? FindSourceFile(string? fileName, string? hint = null)
  {
    if (string.IsNullOrEmpty(fileName))
      return null;
    string up = "";
    for (int level = 0; level < 4; level++, up += "../")
      if (File.Exists(up + fileName))
        return up + fileName;
    if (string.IsNullOrEmpty(hint))
      return null;
    up = "../";
    for (int level = 1; level < 4; level++, up += "../")
      if (File.Exists(up + hint + '/' + fileName))
        return up + hint + '/' + fileName;
    return null;
  }

  /// <summary>Reads a whole text file (UTF-8 unless it has another byte-order mark); false and "" when it is missing or unreadable.</summary>
  public static bool ReadTextFile(string filename, out string content)
  {
    content = string.Empty;
    filename = DataFiles.Resolve(filename);
    if (!File.Exists(filename))
      return false;
    try
    {
      content = File.ReadAllText(filename, Encoding.UTF8);
      return true;
    }
    catch (Exception e) when (e is IOException or UnauthorizedAccessException)
    {
      Log($"Error reading text file '{filename}': {e.Message}");
      return false;
    }
  }

  /// <summary>
  /// <paramref name="path"/> relative to the folder <paramref name="basePath"/>, folders separated by
  /// <paramref name="sep"/>. Both may be relative to the current folder.
  /// </summary>
  public static string MakeRelativePath(string basePath, string path, char sep = '/')
  {
    if (string.IsNullOrEmpty(basePath))
      throw new ArgumentNullException(nameof(basePath));
    if (string.IsNullOrEmpty(path))
      throw new ArgumentNullException(nameof(path));
    string relative = Path.GetRelativePath(Path.GetFullPath(basePath), Path.GetFullPath(path));
    return relative.Replace(Path.DirectorySeparatorChar, sep).Replace(Path.AltDirectorySeparatorChar, sep);
  }
}
