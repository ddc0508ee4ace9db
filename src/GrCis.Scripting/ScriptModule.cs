using System.Collections.Generic;
using System.Reflection;
using GrCis.Scripting.Compilation;

namespace GrCis.Scripting;

/// <summary>
/// A folder of ordinary C# files (with namespaces) compiled into an in-memory assembly that scene
/// scripts reference: a GrCis extension module used without rebuilding the program. Several folders
/// given together are one module (one assembly), so their classes may use each other.
/// </summary>
public sealed class ScriptModule
{
  internal ScriptModule(IReadOnlyList<string> directories, IReadOnlyList<string> files, string contentHash, string cacheKey, Assembly assembly,
                        byte[] image, ScriptLoadContext loadContext, IReadOnlyList<ScriptDiagnostic> warnings,
                        IReadOnlyDictionary<string, SourceMap> sources)
  {
    Directories = directories;
    Directory = directories[0];
    Sources = sources;
    Files = files;
    ContentHash = contentHash;
    Assembly = assembly;
    CacheKey = cacheKey;
    Image = image;
    LoadContext = loadContext;
    Warnings = warnings;
  }

  /// <summary>Full path of the (first) module folder.</summary>
  public string Directory { get; }

  /// <summary>Full paths of every folder compiled into this module, in the order given.</summary>
  public IReadOnlyList<string> Directories { get; }

  /// <summary>The source files compiled (full paths, ordinal order).</summary>
  public IReadOnlyList<string> Files { get; }

  /// <summary>SHA-256 (hex) over the paths and contents of the folders' <c>*.cs</c> files (the scene scripts left out too).</summary>
  public string ContentHash { get; }

  /// <summary>The loaded module assembly.</summary>
  public Assembly Assembly { get; }

  /// <summary>Scene scripts found in the folder and left out of the module (full paths).</summary>
  public IReadOnlyList<string> SkippedScripts { get; internal set; } = [];

  /// <summary>Compiler warnings (the module compiled).</summary>
  public IReadOnlyList<ScriptDiagnostic> Warnings { get; }

  public string AssemblyName => Assembly.GetName().Name!;

  /// <summary>
  /// The module's identity in the compiled-script cache: its folders, every file's path and content, the modules
  /// compiled before it, the library and the compiler options (see <see cref="Caching.CacheKeys"/>). Its assembly is
  /// named after it, so a script compiled against it finds it again in another process.
  /// </summary>
  internal string CacheKey { get; }

  /// <summary>The assembly's bytes: scripts compiled later reference them.</summary>
  internal byte[] Image { get; }

  /// <summary>The XML documentation of the module's doc comments (empty when it has none), for the editor's hover and completion.</summary>
  internal byte[] Documentation { get; init; } = [];

  internal ScriptLoadContext LoadContext { get; }

  /// <summary>The compiled files, to map a stack frame back to the user's line.</summary>
  internal IReadOnlyDictionary<string, SourceMap> Sources { get; }

  /// <summary>Types compiled under a suffixed name because the library has one of the same full name (scripts get aliases).</summary>
  internal IReadOnlyList<ShadowedLibraryTypes.Renamed> Renamed { get; init; } = [];
}
