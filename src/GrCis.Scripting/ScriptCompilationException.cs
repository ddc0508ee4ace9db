using System;
using System.Collections.Generic;
using System.Linq;

namespace GrCis.Scripting;

/// <summary>A scene script or a module did not compile. The message lists every error, one per line.</summary>
public sealed class ScriptCompilationException : Exception
{
  public ScriptCompilationException(string path, IReadOnlyList<ScriptDiagnostic> diagnostics)
    : base(BuildMessage(path, diagnostics))
  {
    Path = path;
    Diagnostics = diagnostics;
  }

  /// <summary>The script file or module folder that failed.</summary>
  public string Path { get; }

  /// <summary>All diagnostics of the compilation (errors first, then warnings).</summary>
  public IReadOnlyList<ScriptDiagnostic> Diagnostics { get; }

  /// <summary>Only the errors.</summary>
  public IEnumerable<ScriptDiagnostic> Errors => Diagnostics.Where(d => d.IsError);

  static string BuildMessage(string path, IReadOnlyList<ScriptDiagnostic> diagnostics)
  {
    var errors = diagnostics.Where(d => d.IsError).ToList();
    string head = $"{path}: {errors.Count} compilation error{(errors.Count == 1 ? "" : "s")}";
    return errors.Count == 0 ? head : head + Environment.NewLine + string.Join(Environment.NewLine, errors);
  }
}
