using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Threading.Tasks;

namespace GrCis.Scripting.Compilation;

/// <summary>
/// Loads a compiled script or module (fresh or from the compiled-script cache) into its own collectible
/// context. Uses no compiler type, so a script found in the cache runs without loading Roslyn at all.
/// </summary>
internal static class ScriptLoader
{
  public static CompiledScript LoadScript(string path, string key, ScriptImage image, IReadOnlyList<ScriptModule> modules)
  {
    var context = new ScriptLoadContext(image.AssemblyName, ModuleMap(modules));
    try
    {
      Assembly assembly = context.LoadFromStream(new MemoryStream(image.Assembly, writable: false), new MemoryStream(image.Pdb, writable: false));
      MethodInfo method = assembly.GetType(image.EntryType, throwOnError: true)!
        .GetMethod(image.EntryMethod, BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Static)
        ?? throw new InvalidOperationException($"{path}: the script entry point {image.EntryMethod} was not found.");
      var factory = method.CreateDelegate<Func<object?[], Task<object?>>>();
      return new CompiledScript(path, key, factory, context, image.Warnings, image.Map, modules);
    }
    catch
    {
      context.Unload();
      throw;
    }
  }

  /// <param name="contentHash">What the folders hold (<see cref="Caching.CacheKeys.ModuleContent"/>).</param>
  /// <param name="cacheKey">The module's key in the compiled-script cache (scripts compiled against it name it in theirs).</param>
  public static ScriptModule LoadModule(IReadOnlyList<string> directories, string contentHash, string cacheKey, ModuleImage image,
                                        IReadOnlyList<ScriptModule> earlier)
  {
    var context = new ScriptLoadContext(image.AssemblyName, ModuleMap(earlier));
    try
    {
      Assembly assembly = context.LoadFromStream(new MemoryStream(image.Assembly, writable: false), new MemoryStream(image.Pdb, writable: false));
      return new ScriptModule(directories, image.Files, contentHash, cacheKey, assembly, image.Assembly, context, image.Warnings, image.Maps)
      {
        Renamed = image.Renamed,
        SkippedScripts = image.SkippedScripts,
        Documentation = image.Documentation,
      };
    }
    catch
    {
      context.Unload();
      throw;
    }
  }

  static Dictionary<string, Assembly> ModuleMap(IReadOnlyList<ScriptModule> modules) =>
    modules.ToDictionary(m => m.AssemblyName, m => m.Assembly);
}
