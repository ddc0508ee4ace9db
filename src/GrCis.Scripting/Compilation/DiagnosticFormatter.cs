using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.Text;

namespace GrCis.Scripting.Compilation;

/// <summary>Turns Roslyn diagnostics into <see cref="ScriptDiagnostic"/>s with 1-based positions in the user's file.</summary>
internal static class DiagnosticFormatter
{
  /// <param name="sources">Instrumented trees and their original text: positions are reported in the original.</param>
  public static List<ScriptDiagnostic> Convert(IEnumerable<Diagnostic> diagnostics, string fallbackPath,
                                               IReadOnlyDictionary<SyntaxTree, InstrumentedSource>? sources = null)
  {
    return diagnostics
      .Where(d => d.Severity is DiagnosticSeverity.Error or DiagnosticSeverity.Warning)
      .OrderBy(d => d.Severity == DiagnosticSeverity.Error ? 0 : 1)
      .ThenBy(d => d.Location.GetMappedLineSpan().Path)
      .ThenBy(d => d.Location.SourceSpan.Start)
      .Select(d => Convert(d, fallbackPath, sources))
      .ToList();
  }

  static ScriptDiagnostic Convert(Diagnostic d, string fallbackPath, IReadOnlyDictionary<SyntaxTree, InstrumentedSource>? sources)
  {
    FileLinePositionSpan span = d.Location.GetMappedLineSpan();
    bool hasPosition = d.Location.IsInSource;
    string path = hasPosition && !string.IsNullOrEmpty(span.Path) ? span.Path : fallbackPath;
    LinePosition start = span.StartLinePosition;
    if (hasPosition && !span.HasMappedPath && sources != null && d.Location.SourceTree is SyntaxTree tree &&
        sources.TryGetValue(tree, out InstrumentedSource? source))
      start = source.Original.Lines.GetLinePosition(source.ToOriginal(d.Location.SourceSpan.Start));
    int line = hasPosition ? start.Line + 1 : 1;
    int column = hasPosition ? start.Character + 1 : 1;
    string severity = d.Severity == DiagnosticSeverity.Error ? "error" : "warning";
    return new ScriptDiagnostic(path, line, column, severity, d.Id, d.GetMessage(CultureInfo.InvariantCulture));
  }
}
