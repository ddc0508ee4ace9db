using System;
using GrCis.Scripting;

namespace GrCis.Cli;

/// <summary>
/// How scene-script errors reach the user. A compilation error prints every diagnostic as
/// <c>path(line,col): error CSxxxx: message</c> (then one summary line), a script that throws prints
/// its message with the script line, a malformed parameter value is a usage error.
/// </summary>
public static class ScriptErrors
{
  /// <summary>True when <paramref name="e"/> is a script error this class reports.</summary>
  public static bool Handles(Exception e) =>
    e is ScriptCompilationException || Runtime(e) != null;

  /// <summary>Compiler errors printed at most (all warnings are).</summary>
  public const int MaxErrorsShown = 25;

  /// <summary>Writes the error to stderr and returns the exit code.</summary>
  public static int Report(Exception e, CliEnvironment env)
  {
    if (e is ScriptCompilationException { Diagnostics: [{ Id: ScriptDiagnostic.EmptyScriptId or ScriptDiagnostic.BinaryScriptId } only] } whole)
    {
      // Nothing the compiler could point at: one line about the file.
      string why = only.Id == ScriptDiagnostic.EmptyScriptId
        ? "is empty (only whitespace or comments): it must build the scene (scene.Intersectable, scene.Camera, scene.Sources)"
        : "is not a C# scene script: " + only.Message[(only.Message.IndexOf(':', StringComparison.Ordinal) + 2)..];
      env.Error.WriteLine($"grcis: error: scene script '{whole.Path}' {why}");
      return ExitCodes.Failure;
    }
    if (e is ScriptCompilationException ce)
    {
      int errors = 0, shown = 0;
      foreach (ScriptDiagnostic d in ce.Diagnostics)
      {
        // The first errors matter; hundreds (a file that is not C#) would bury them.
        if (!d.IsError || shown < MaxErrorsShown)
        {
          env.Error.WriteLine(d.ToString());
          if (d.IsError)
            shown++;
        }
        if (d.IsError)
          errors++;
      }
      string what = ce.Path.EndsWith(".cs", StringComparison.OrdinalIgnoreCase) ? "scene script" : "module";
      string hidden = errors > shown ? $", the first {shown} shown" : "";
      env.Error.WriteLine($"grcis: error: {what} '{ce.Path}' did not compile ({errors} error{(errors == 1 ? "" : "s")}{hidden})");
      return ExitCodes.Failure;
    }

    ScriptRuntimeException re = Runtime(e)!;
    if (re.InnerException is ScriptParameterException pe)
    {
      env.Error.WriteLine($"grcis: error: invalid --param: {pe.Message} ({System.IO.Path.GetFileName(re.Path)}, line {re.Line})");
      return ExitCodes.Usage;
    }
    string hint = re.InnerException is OutOfMemoryException ? Jobs.MemoryLimit.Hint() : "";
    env.Error.WriteLine("grcis: error: " + Flatten(re.Message) + hint);
    return ExitCodes.Failure;
  }

  static ScriptRuntimeException? Runtime(Exception e)
  {
    for (Exception? x = e; x != null; x = x.InnerException)
      if (x is ScriptRuntimeException sre)
        return sre;
    return null;
  }

  static string Flatten(string message) =>
    message.Replace("\r\n", " ", StringComparison.Ordinal).Replace('\n', ' ').Replace('\r', ' ').Trim();
}
