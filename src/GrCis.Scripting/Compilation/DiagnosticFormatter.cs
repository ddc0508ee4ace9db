using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using Microsoft.CodeAnalysis;

namespace GrCis.Scripting.Compilation;

/// <summary>Turns Roslyn diagnostics into <see cref="ScriptDiagnostic"/>s with 1-based positions in the user's file.</summary>
internal static class DiagnosticFormatter
{
  public static List<ScriptDiagnostic> Convert(IEnumerable<Diagnostic> diagnostics, string fallbackPath)
  {
    return diagnostics
      .Where(d => d.Severity is DiagnosticSeverity.Error or DiagnosticSeverity.Warning)
      .OrderBy(d => d.Severity == DiagnosticSeverity.Error ? 0 : 1)
      .ThenBy(d => d.Location.GetMappedLineSpan().Path)
      .ThenBy(d => d.Location.SourceSpan.Start)
      .Select(d => Convert(d, fallbackPath))
      .ToList();
  }

  static ScriptDiagnostic Convert(Diagnostic d, string fallbackPath)
  {
    FileLinePositionSpan span = d.Location.GetMappedLineSpan();
    bool hasPosition = d.Location.IsInSource;
    string path = hasPosition && !string.IsNullOrEmpty(span.Path) ? span.Path : fallbackPath;
    int line = hasPosition ? span.StartLinePosition.Line + 1 : 1;
    int column = hasPosition ? span.StartLinePosition.Character + 1 : 1;
    string severity = d.Severity == DiagnosticSeverity.Error ? "error" : "warning";
    return new ScriptDiagnostic(path, line, column, severity, d.Id, d.GetMessage(CultureInfo.InvariantCulture));
  }
}
