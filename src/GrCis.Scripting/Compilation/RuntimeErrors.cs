using System;
using System.Diagnostics;
using System.IO;

namespace GrCis.Scripting.Compilation;

/// <summary>Maps an exception thrown by script code to the script's own line via the emitted PDB.</summary>
internal static class RuntimeErrors
{
  public static ScriptRuntimeException Wrap(Exception ex, string scriptPath, InstrumentedSource source)
  {
    if (ex is ScriptRuntimeException sre && sre.Path == scriptPath)
      return sre;
    FindScriptFrame(ex, scriptPath, source, out int line, out int column);
    return new ScriptRuntimeException(scriptPath, line, column, ex);
  }

  /// <summary>The innermost frame of <paramref name="ex"/> (or its inner exceptions) located in the script.</summary>
  public static bool FindScriptFrame(Exception ex, string scriptPath, InstrumentedSource source, out int line, out int column)
  {
    StringComparison cmp = OperatingSystem.IsWindows() ? StringComparison.OrdinalIgnoreCase : StringComparison.Ordinal;
    for (Exception? e = ex; e != null; e = e.InnerException)
    {
      StackFrame[] frames = new StackTrace(e, fNeedFileInfo: true).GetFrames();
      foreach (StackFrame f in frames)
      {
        string? file = f.GetFileName();
        if (file != null && f.GetFileLineNumber() > 0 &&
            string.Equals(Path.GetFullPath(file), scriptPath, cmp))
        {
          line = f.GetFileLineNumber();
          column = source.OriginalColumn(line, f.GetFileColumnNumber());
          return true;
        }
      }
    }
    line = column = 0;
    return false;
  }
}
