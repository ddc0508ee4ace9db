using System;
using System.Collections.Generic;
using System.Threading.Tasks;
using GrCis.Scripting.Compilation;
using Rendering;
using Rendering.Execution;

namespace GrCis.Scripting;

/// <summary>
/// A scene script compiled once. <see cref="Run(ScriptGlobals)"/> executes the compiled code; it may be
/// called any number of times, from any number of threads (each call gets its own script instance).
/// </summary>
public sealed class CompiledScript
{
  readonly Func<object?[], Task<object?>> factory;
  readonly InstrumentedSource source;
  ScriptLoadContext? loadContext;

  internal CompiledScript(string path, string contentHash, Func<object?[], Task<object?>> factory,
                          ScriptLoadContext loadContext, IReadOnlyList<ScriptDiagnostic> warnings, InstrumentedSource source)
  {
    this.source = source;
    Path = path;
    ContentHash = contentHash;
    this.factory = factory;
    this.loadContext = loadContext;
    Warnings = warnings;
  }

  /// <summary>Full path of the script file (as used in messages).</summary>
  public string Path { get; }

  /// <summary>Hex SHA-256 of the cache key (path, content, modules).</summary>
  public string ContentHash { get; }

  /// <summary>Compiler warnings (the script compiled).</summary>
  public IReadOnlyList<ScriptDiagnostic> Warnings { get; }

  /// <summary>Runs the script with the given globals.</summary>
  /// <exception cref="ScriptRuntimeException">The script threw; the message names its line.</exception>
  public void Run(ScriptGlobals globals)
  {
    ArgumentNullException.ThrowIfNull(globals);

    // Slot 0 holds the globals; the script's submission object stores itself in slot 1.
    object?[] submissionStates = { globals, null };
    // Data files named relative to the script are found beside it (as GrCis scripts expect).
    using Utilities.DataFiles.Scope folder = Utilities.DataFiles.UseScriptDirectory(System.IO.Path.GetDirectoryName(Path));
    try
    {
      factory(submissionStates).GetAwaiter().GetResult();
    }
    catch (OperationCanceledException) when (Interruption.Current.IsCancellationRequested)
    {
      // The host stopped the script (see Interruption): not an error of the script.
      throw;
    }
    catch (Exception ex)
    {
      throw RuntimeErrors.Wrap(ex, Path, source);
    }
  }

  /// <summary>Runs the script with globals <c>scene</c>, <c>param</c>, <c>context</c>.</summary>
  public void Run(IRayScene scene, string? param, Dictionary<string, object> context) =>
    Run(new ScriptGlobals(scene, param, context));

  /// <summary>
  /// For an exception thrown later by code the script created (a texture, camera or solid class declared
  /// in it, called while rendering): the same exception wrapped with the script line that threw, or null
  /// when no frame of the exception lies in this script.
  /// </summary>
  public ScriptRuntimeException? FindScriptLine(Exception ex)
  {
    ArgumentNullException.ThrowIfNull(ex);
    if (ex is ScriptRuntimeException sre && sre.Path == Path)
      return sre;
    return RuntimeErrors.FindScriptFrame(ex, Path, source, out int line, out int column)
      ? new ScriptRuntimeException(Path, line, column, ex)
      : null;
  }

  /// <summary>Starts unloading the script's code; it goes once no object created by the script is alive.</summary>
  internal void Unload()
  {
    ScriptLoadContext? ctx = loadContext;
    loadContext = null;
    ctx?.Unload();
  }
}
