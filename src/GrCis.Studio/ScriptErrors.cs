using System.Collections.Generic;
using System.IO;
using System.Linq;
using GrCis.Scripting;

namespace GrCis.Studio;

/// <summary>
/// The diagnostics the editor marks: those in the script it shows. A module's diagnostics name another file, so they
/// stay in the message and are not drawn at the same line numbers of the script.
/// </summary>
internal static class ScriptErrors
{
  public static IReadOnlyList<ScriptError> In(IEnumerable<ScriptDiagnostic> diagnostics, string? scriptPath)
  {
    if (scriptPath == null)
      return [];
    string full = Path.GetFullPath(scriptPath);
    return diagnostics.Where(d => d.Path == full)
      .Select(d => new ScriptError(d.Line, d.Column, d.Severity, d.Id, d.Message)).ToList();
  }
}
