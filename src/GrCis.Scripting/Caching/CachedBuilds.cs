using System;
using System.Collections.Generic;
using System.Runtime.CompilerServices;
using GrCis.Scripting.Compilation;

namespace GrCis.Scripting.Caching;

/// <summary>
/// A script or module from the compiled-script cache when it holds one, else compiled (and stored). Either way
/// the image is loaded by <see cref="ScriptLoader"/>, so nothing differs after. The compiler is reached only
/// through the methods marked not to be inlined: on a hit no Roslyn assembly is loaded at all.
/// </summary>
internal static class CachedBuilds
{
  /// <param name="beforeCompile">Called just before the script is compiled (not on a hit).</param>
  /// <returns>The loaded script, and whether it was compiled (false: loaded from the cache).</returns>
  public static (CompiledScript Script, bool Compiled) Script(ScriptCache? cache, string path, string source, string memoryKey,
                                                              IReadOnlyList<ScriptModule> modules, bool optimize, Action? beforeCompile = null)
  {
    string? key = cache == null ? null : CacheKeys.Script(path, source, modules, optimize);
    if (key != null && cache!.ReadScript(key) is ScriptImage cached)
    {
      try
      {
        return (ScriptLoader.LoadScript(path, memoryKey, cached, modules), false);
      }
      catch (Exception e) when (e is not OutOfMemoryException)
      {
        cache.Reject(key);
      }
    }
    beforeCompile?.Invoke();
    ScriptImage image = CompileScript(path, source, memoryKey, modules, optimize);
    if (key != null)
      cache!.Write(key, image);
    return (ScriptLoader.LoadScript(path, memoryKey, image, modules), true);
  }

  /// <param name="beforeCompile">Called just before the module is compiled (not on a hit).</param>
  /// <returns>The loaded module, and whether it was compiled (false: loaded from the cache).</returns>
  public static (ScriptModule Module, bool Compiled) Module(ScriptCache? cache, IReadOnlyList<string> directories,
                                                            IReadOnlyList<ModuleFiles.Candidate> candidates, string contentHash,
                                                            string key, IReadOnlyList<ScriptModule> earlier, bool optimize,
                                                            Action? beforeCompile = null)
  {
    if (cache?.ReadModule(key) is ModuleImage cached)
    {
      try
      {
        return (ScriptLoader.LoadModule(directories, contentHash, key, cached, earlier), false);
      }
      catch (Exception e) when (e is not OutOfMemoryException)
      {
        cache.Reject(key);
      }
    }
    beforeCompile?.Invoke();
    ModuleImage image = CompileModule(directories, candidates, key, earlier, optimize);
    cache?.Write(key, image);
    return (ScriptLoader.LoadModule(directories, contentHash, key, image, earlier), true);
  }

  [MethodImpl(MethodImplOptions.NoInlining)]
  static ScriptImage CompileScript(string path, string source, string memoryKey, IReadOnlyList<ScriptModule> modules, bool optimize) =>
    ScriptCompiler.CompileScript(path, source, memoryKey, modules, optimize);

  [MethodImpl(MethodImplOptions.NoInlining)]
  static ModuleImage CompileModule(IReadOnlyList<string> directories, IReadOnlyList<ModuleFiles.Candidate> candidates, string key,
                                   IReadOnlyList<ScriptModule> earlier, bool optimize) =>
    ScriptCompiler.CompileModule(directories, candidates, key, earlier, optimize);
}
