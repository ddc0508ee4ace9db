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
  // The script's file and its modules' files, by full path: where a runtime error may be located.
  readonly Dictionary<string, SourceMap> sources;
  ScriptLoadContext? loadContext;

  internal CompiledScript(string path, string contentHash, Func<object?[], Task<object?>> factory,
                          ScriptLoadContext loadContext, IReadOnlyList<ScriptDiagnostic> warnings, SourceMap source,
                          IReadOnlyList<ScriptModule> modules)
  {
    sources = new Dictionary<string, SourceMap>(RuntimeErrors.PathComparer) { [path] = source };
    foreach (ScriptModule m in modules)
      foreach ((string file, SourceMap s) in m.Sources)
        sources.TryAdd(file, s);
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
      throw RuntimeErrors.Wrap(ex, Path, sources);
    }
  }

  /// <summary>Runs the script with globals <c>scene</c>, <c>param</c>, <c>context</c>.</summary>
  public void Run(IRayScene scene, string? param, Dictionary<string, object> context)
  {
    var globals = new ScriptGlobals(scene, param, context);
    if (globals.scriptFilePath.Length == 0)
      globals.scriptFilePath = Path;
    Run(globals);
  }

  /// <summary>
  /// For an exception thrown later by code the script or its modules created (a texture, camera or solid
  /// class, called while rendering): the same exception wrapped with the innermost line of the script or a
  /// module file that threw, or null when no frame of the exception lies in them.
  /// </summary>
  public ScriptRuntimeException? FindScriptLine(Exception ex)
  {
    ArgumentNullException.ThrowIfNull(ex);
    if (ex is ScriptRuntimeException sre && sources.ContainsKey(sre.Path))
      return sre;
    return RuntimeErrors.Locate(ex, sources);
  }

  /// <summary>Starts unloading the script's code; it goes once no object created by the script is alive.</summary>
  internal void Unload()
  {
    ScriptLoadContext? ctx = loadContext;
    loadContext = null;
    ctx?.Unload();
  }
}
