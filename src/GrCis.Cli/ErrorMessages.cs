using System;
using System.Reflection;

namespace GrCis.Cli;

/// <summary>
/// Turns an exception into the one line a user sees. Errors that carry a source location (a mesh
/// file's line, a script's line) print as <c>file(line): message</c>, like compilers do.
/// </summary>
public static class ErrorMessages
{
  /// <summary>One line for <paramref name="e"/>: the innermost exception that names a file and line wins.</summary>
  public static string OneLine(Exception e)
  {
    ArgumentNullException.ThrowIfNull(e);
    for (Exception? x = e; x != null; x = x.InnerException)
      if (TryGetLocation(x, out string file, out int line))
        return Flatten(WithLocation(file, line, x.Message));
    return Flatten(Innermost(e).Message);
  }

  /// <summary><c>file(line): message</c>, without repeating a location the message already starts with.</summary>
  public static string WithLocation(string file, int line, string message)
  {
    string prefix = $"{file}({line})";
    if (message.StartsWith(prefix, StringComparison.Ordinal))
      return message;
    return $"{prefix}: {message}";
  }

  /// <summary>
  /// Finds a file name and a positive line number on an exception by property name (FileName, File or
  /// Path; Line or LineNumber), so format errors from any loader (OBJ meshes, scripts) are reported
  /// with their location without the command line depending on each exception type.
  /// </summary>
  public static bool TryGetLocation(Exception e, out string file, out int line)
  {
    file = string.Empty;
    line = 0;
    Type t = e.GetType();
    string? f = ReadString(t, e, "FileName") ?? ReadString(t, e, "File") ?? ReadString(t, e, "Path");
    int? l = ReadInt(t, e, "Line") ?? ReadInt(t, e, "LineNumber");
    if (string.IsNullOrEmpty(f) || l is not > 0)
      return false;
    file = f;
    line = l.Value;
    return true;
  }

  static Exception Innermost(Exception e)
  {
    // Wrappers that add nothing a user needs (reflection, aggregate of one) are skipped.
    while (e is TargetInvocationException or AggregateException { InnerExceptions.Count: 1 } && e.InnerException != null)
      e = e.InnerException;
    return e;
  }

  static string? ReadString(Type t, object o, string name) =>
    t.GetProperty(name, BindingFlags.Public | BindingFlags.Instance) is { PropertyType: var pt } p && pt == typeof(string)
      ? (string?)p.GetValue(o)
      : null;

  static int? ReadInt(Type t, object o, string name) =>
    t.GetProperty(name, BindingFlags.Public | BindingFlags.Instance) is { PropertyType: var pt } p && pt == typeof(int)
      ? (int?)p.GetValue(o)
      : null;

  static string Flatten(string message) =>
    message.Replace("\r\n", " ", StringComparison.Ordinal).Replace('\n', ' ').Replace('\r', ' ').Trim();
}
