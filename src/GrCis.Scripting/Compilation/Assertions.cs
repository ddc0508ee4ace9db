using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Reflection;
using System.Runtime.Loader;

namespace GrCis.Scripting.Compilation;

/// <summary>
/// Modules are compiled with <c>DEBUG</c> and <c>TRACE</c> defined, as the Debug build of a student's GrCis
/// project; there a failing <c>Debug.Assert</c> showed a dialog and went on. In .NET 10 it ends the process
/// at once (fail-fast), taking the render and the user's other work with it. Instead a failing assertion
/// is a warning naming its place in the script or module, written once per place to the standard error,
/// and the code goes on as GrCis's did after the dialog.
/// </summary>
/// <remarks>
/// .NET sends <c>Debug.Assert</c> and <c>Trace.Assert</c> to the process-wide <see cref="Trace.Listeners"/>,
/// whose default listener ends the process; so this listener is installed once per process, by the first
/// script host, and the default one is told not to.
/// </remarks>
internal sealed class Assertions : TraceListener
{
  /// <summary>Id of the warning for a failed assertion.</summary>
  public const string Id = "GRCIS006";

  static readonly object installLock = new();
  static bool installed;

  readonly HashSet<string> reported = new(StringComparer.Ordinal);

  /// <summary>Installs the listener once per process (later calls do nothing).</summary>
  public static void Install()
  {
    lock (installLock)
    {
      if (installed)
        return;
      foreach (TraceListener l in Trace.Listeners)
        if (l is DefaultTraceListener d)
          d.AssertUiEnabled = false;
      Trace.Listeners.Add(new Assertions());
      installed = true;
    }
  }

  public override void Fail(string? message, string? detailMessage)
  {
    foreach (StackFrame frame in new StackTrace(1, fNeedFileInfo: true).GetFrames())
    {
      MethodBase? method = frame.GetMethod();
      string? file = frame.GetFileName();
      if (method == null || file == null || frame.GetFileLineNumber() <= 0 ||
          AssemblyLoadContext.GetLoadContext(method.Module.Assembly) is not ScriptLoadContext)
        continue;
      string place = $"{file}({frame.GetFileLineNumber()})";
      lock (reported)
        if (!reported.Add(place))
          return;
      string text = string.IsNullOrEmpty(message) ? "" : ": " + message;
      if (!string.IsNullOrEmpty(detailMessage))
        text += " (" + detailMessage + ")";
      TextWriter output = Console.Error;
      lock (output)
        output.WriteLine($"{place}: warning {Id}: assertion failed{text}; going on (reported once per place)");
      return;
    }
  }

  // Debug.Write/Trace.Write output is left to the other listeners.
  public override void Write(string? message) { }

  public override void WriteLine(string? message) { }
}
