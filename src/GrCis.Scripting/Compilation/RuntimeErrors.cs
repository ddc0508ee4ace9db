using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;

namespace GrCis.Scripting.Compilation;

/// <summary>Maps an exception thrown by a script's or a module's code to the user's own line via the emitted PDBs.</summary>
internal static class RuntimeErrors
{
  /// <summary>How file names of stack frames are compared with the user's files.</summary>
  public static StringComparer PathComparer => OperatingSystem.IsWindows() ? StringComparer.OrdinalIgnoreCase : StringComparer.Ordinal;

  /// <summary>The exception wrapped with the place in the user's code that threw; without one, with the script's path and no line.</summary>
  public static ScriptRuntimeException Wrap(Exception ex, string scriptPath, IReadOnlyDictionary<string, SourceMap> sources)
  {
    if (ex is ScriptRuntimeException sre && sources.ContainsKey(sre.Path))
      return sre;
    return Locate(ex, sources) ?? new ScriptRuntimeException(scriptPath, 0, 0, ex);
  }

  /// <summary>
  /// The exception wrapped with the innermost frame of <paramref name="ex"/> (or of an inner exception) that lies in
  /// one of <paramref name="sources"/> (the script and its modules), or null when none does.
  /// </summary>
  public static ScriptRuntimeException? Locate(Exception ex, IReadOnlyDictionary<string, SourceMap> sources)
  {
    for (Exception? e = ex; e != null; e = e.InnerException)
    {
      StackFrame[] frames = new StackTrace(e, fNeedFileInfo: true).GetFrames();
      // A recursion guard throws on entry to the method one call too deep: its caller's line is the recursive call.
      ScriptRuntimeException? entry = null;
      foreach (StackFrame f in frames)
      {
        string? file = f.GetFileName();
        if (file == null || f.GetFileLineNumber() <= 0)
          continue;
        string full = Path.GetFullPath(file);
        if (!sources.TryGetValue(full, out SourceMap? source))
          continue;
        int line = f.GetFileLineNumber();
        // The exception that passed through the user's line (not a wrapper the renderer added around it).
        var found = new ScriptRuntimeException(full, line, source.OriginalColumn(line, f.GetFileColumnNumber()), e);
        if (e is not Rendering.Execution.RecursionTooDeepException || entry != null)
          return found;
        entry = found;
      }
      if (entry != null)
        return entry;
    }
    return null;
  }
}
