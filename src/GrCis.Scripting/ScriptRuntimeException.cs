using System;

namespace GrCis.Scripting;

/// <summary>A scene script threw while running. Names the script line that was executing.</summary>
public sealed class ScriptRuntimeException : Exception
{
  public ScriptRuntimeException(string path, int line, int column, Exception inner)
    : base(BuildMessage(path, line, column, inner), inner)
  {
    Path = path;
    Line = line;
    Column = column;
  }

  /// <summary>The script file.</summary>
  public string Path { get; }

  /// <summary>1-based script line of the innermost script frame; 0 when unknown.</summary>
  public int Line { get; }

  /// <summary>1-based column; 0 when unknown.</summary>
  public int Column { get; }

  static string BuildMessage(string path, int line, int column, Exception inner)
  {
    string where = line > 0 ? $"{path}({line},{Math.Max(column, 1)})" : path;
    return $"{where}: runtime error: {inner.GetType().Name}: {inner.Message}";
  }
}
