using System;
using System.Collections.Generic;
using GrCis.Scripting;

namespace GrCis.Interactive;

/// <summary>
/// A message for the user (<see cref="DemoController.Error"/>) and the script places it is about, as objects: a
/// compiler's diagnostics, or the script line a runtime error came from. A front end marks these in its editor
/// rather than reading positions back out of the message.
/// </summary>
public sealed class DemoErrorEventArgs : EventArgs
{
  public DemoErrorEventArgs(string message, IReadOnlyList<ScriptDiagnostic> diagnostics)
  {
    Message = message;
    Diagnostics = diagnostics;
  }

  /// <summary>The text for the user (no stack trace); compiler messages name file, line and column as grcis prints them.</summary>
  public string Message { get; }

  /// <summary>Places in the scene script or its modules (each names its file); empty when the error is not about one.</summary>
  public IReadOnlyList<ScriptDiagnostic> Diagnostics { get; }

  /// <summary>The message with the diagnostics found in <paramref name="cause"/> and the exceptions it wraps.</summary>
  public static DemoErrorEventArgs For(string message, Exception? cause) => new(message, DiagnosticsOf(cause));

  /// <summary>A compilation's diagnostics, or one error at the script line that threw; nothing for other exceptions.</summary>
  public static IReadOnlyList<ScriptDiagnostic> DiagnosticsOf(Exception? cause)
  {
    for (Exception? e = cause; e != null; e = e.InnerException)
    {
      if (e is ScriptCompilationException compiled)
        return compiled.Diagnostics;
      if (e is ScriptRuntimeException { Line: > 0 } thrown)
      {
        Exception inner = thrown.InnerException!;
        return [new ScriptDiagnostic(thrown.Path, thrown.Line, Math.Max(thrown.Column, 1), "error", inner.GetType().Name, inner.Message)];
      }
    }
    return Array.Empty<ScriptDiagnostic>();
  }
}
