using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Security.Cryptography;
using System.Text;
using System.Threading;
using GrCis.Scripting.Compilation;
using Microsoft.CodeAnalysis;
using Rendering;
using Utilities;

namespace GrCis.Scripting;

/// <summary>
/// Compiles and runs GrCis scene scripts. A script is compiled once per (path, content, modules) and
/// cached (least recently used entries are evicted and their code unloaded); every further run, on any
/// thread, executes the compiled code. Thread-safe.
/// </summary>
public sealed class ScriptHost : IDisposable
{
  /// <summary>How many compiled scripts a host keeps by default.</summary>
  public const int DefaultCacheCapacity = 16;

  readonly object sync = new();
  readonly LruCache<string, Lazy<CompiledScript>> cache;
  readonly List<ScriptModule> modules = new();
  int compilations;
  int moduleCompilations;

  /// <param name="cacheCapacity">How many compiled scripts to keep (least recently used ones are unloaded).</param>
  /// <param name="optimizeScripts">
  /// Compile script code with optimisations: classes declared in scripts (textures, cameras, solids)
  /// run faster, but the JIT may inline script methods, and then a runtime error cannot always name its
  /// script line. Off by default: readable errors first.
  /// </param>
  public ScriptHost(int cacheCapacity = DefaultCacheCapacity, bool optimizeScripts = false)
  {
    CacheCapacity = cacheCapacity;
    OptimizeScripts = optimizeScripts;
    cache = new LruCache<string, Lazy<CompiledScript>>(cacheCapacity, static lazy =>
    {
      if (lazy.IsValueCreated)
        lazy.Value.Unload();
    });
  }

  /// <summary>Namespaces scripts see without a <c>using</c>.</summary>
  public static IReadOnlyList<string> DefaultImports => ScriptCompiler.DefaultImports;

  public int CacheCapacity { get; }

  /// <summary>Whether script code is compiled with optimisations (see the constructor).</summary>
  public bool OptimizeScripts { get; }

  /// <summary>Number of script compilations this host has performed (cache hits do not count).</summary>
  public int CompilationCount => Volatile.Read(ref compilations);

  /// <summary>Number of module compilations this host has performed.</summary>
  public int ModuleCompilationCount => Volatile.Read(ref moduleCompilations);

  /// <summary>Compiled scripts currently held by the cache.</summary>
  public int CachedScriptCount
  {
    get
    {
      lock (sync)
        return cache.Count;
    }
  }

  /// <summary>Modules every script compiled from now on references, in the order added.</summary>
  public IReadOnlyList<ScriptModule> Modules
  {
    get
    {
      lock (sync)
        return modules.ToArray();
    }
  }

  /// <summary>
  /// Compiles every <c>*.cs</c> file under <paramref name="directory"/> (recursively) into an in-memory
  /// assembly that scripts (and modules added later) reference, except scene scripts kept in the folder
  /// (files with top-level statements, see <see cref="ScriptModule.SkippedScripts"/>) and build output
  /// (<c>bin/</c>, <c>obj/</c>). Adding an unchanged folder again is a no-op.
  /// </summary>
  /// <exception cref="DirectoryNotFoundException">The folder does not exist.</exception>
  /// <exception cref="ScriptCompilationException">A module file did not compile.</exception>
  public ScriptModule AddModule(string directory)
  {
    ArgumentException.ThrowIfNullOrEmpty(directory);
    string dir = Path.GetFullPath(directory);
    if (!Directory.Exists(dir))
      throw new DirectoryNotFoundException($"Module folder not found: '{dir}'");

    // Scene scripts kept beside the classes, and build output, are not module code.
    var files = new List<string>();
    var sources = new List<string>();
    var trees = new List<SyntaxTree>();
    var scripts = new List<string>();
    foreach (string file in ModuleFiles.Candidates(dir))
    {
      string text = File.ReadAllText(file);
      SyntaxTree tree = ModuleFiles.Parse(file, text);
      if (ModuleFiles.IsSceneScript(tree))
        scripts.Add(file);
      else
      {
        files.Add(file);
        sources.Add(text);
        trees.Add(tree);
      }
    }
    if (files.Count == 0)
      throw new ScriptCompilationException(dir, new[] { new ScriptDiagnostic(dir, 1, 1, "error", "GRCIS001",
        scripts.Count == 0 ? "the module folder holds no *.cs file"
                           : $"the module folder holds only scene scripts ({scripts.Count}), no classes; give a script as the scene, not as --module") });

    var sb = new StringBuilder();
    for (int i = 0; i < files.Count; i++)
      sb.Append(files[i]).Append('\0').Append(sources[i]).Append('\0');

    lock (sync)
    {
      string hash = Hash(sb.ToString());
      ScriptModule? existing = modules.FirstOrDefault(m => m.ContentHash == hash);
      if (existing != null)
        return existing;
      ScriptModule module = ScriptCompiler.CompileModule(dir, files, trees, hash, modules.ToArray());
      module.SkippedScripts = scripts;
      Interlocked.Increment(ref moduleCompilations);
      modules.Add(module);
      return module;
    }
  }

  /// <summary>Compiles the script file (or returns the cached compilation of the same content).</summary>
  /// <exception cref="FileNotFoundException">The script file does not exist.</exception>
  /// <exception cref="ScriptCompilationException">The script did not compile; lists every error.</exception>
  public CompiledScript Compile(string path)
  {
    ArgumentException.ThrowIfNullOrEmpty(path);
    string full = Path.GetFullPath(path);
    if (!File.Exists(full))
      throw new FileNotFoundException($"Scene script not found: '{full}'", full);
    return CompileSource(File.ReadAllText(full), full);
  }

  /// <summary>Compiles script text; <paramref name="path"/> names it in messages and stack traces.</summary>
  /// <exception cref="ScriptCompilationException">The script did not compile; lists every error.</exception>
  public CompiledScript CompileSource(string source, string path)
  {
    ArgumentNullException.ThrowIfNull(source);
    ArgumentException.ThrowIfNullOrEmpty(path);
    string full = Path.GetFullPath(path);

    Lazy<CompiledScript> entry;
    string key;
    lock (sync)
    {
      ScriptModule[] mods = modules.ToArray();
      key = Hash(full + "\0" + source + "\0" + string.Join("|", mods.Select(m => m.ContentHash)));
      if (!cache.TryGet(key, out entry))
      {
        entry = new Lazy<CompiledScript>(() =>
        {
          Interlocked.Increment(ref compilations);
          return ScriptCompiler.CompileScript(full, source, key, mods, OptimizeScripts);
        }, LazyThreadSafetyMode.ExecutionAndPublication);
        cache.Add(key, entry);
      }
    }

    // Compile outside the lock: different scripts compile in parallel, the same one compiles once.
    try
    {
      return entry.Value;
    }
    catch
    {
      lock (sync)
        if (cache.TryGet(key, out var current) && ReferenceEquals(current, entry))
          cache.Remove(key);
      throw;
    }
  }

  /// <summary>Compiles (once) and runs the script file with the context protocol; see <see cref="Run"/>.</summary>
  public ScriptScene Load(string path, string? param = null, Dictionary<string, object>? context = null) =>
    Run(Compile(path), param, context);

  /// <summary>
  /// Runs a compiled script with GrCis's context protocol. When <paramref name="context"/> holds fewer
  /// than two entries, the script is first called with <c>Preprocessing = true</c> (and a throw-away
  /// scene): it may simulate once, store results in a free context key and <c>return;</c>. Then the
  /// regular call fills <paramref name="scene"/> (a new <see cref="DefaultRayScene"/> by default).
  /// </summary>
  /// <exception cref="ScriptRuntimeException">The script threw; the message names its line.</exception>
  public ScriptScene Run(CompiledScript script, string? param = null, Dictionary<string, object>? context = null, IRayScene? scene = null)
  {
    ArgumentNullException.ThrowIfNull(script);
    context ??= new Dictionary<string, object>();
    bool preprocess = context.Count < 2;
    context[PropertyName.CTX_SCRIPT_PATH] = script.Path;

    if (preprocess)
    {
      context[PropertyName.CTX_PREPROCESSING] = true;
      var scratch = new DefaultRayScene();
      context[PropertyName.CTX_SCENE] = scratch;
      try
      {
        script.Run(scratch, param, context);
      }
      finally
      {
        context.Remove(PropertyName.CTX_PREPROCESSING);
      }
    }

    scene ??= new DefaultRayScene();
    context[PropertyName.CTX_SCENE] = scene;
    script.Run(scene, param, context);

    return ReadSettings(new ScriptScene(script, scene, context, preprocess));
  }

  /// <summary>Unloads every cached script.</summary>
  public void ClearCache()
  {
    lock (sync)
      cache.Clear();
  }

  public void Dispose()
  {
    lock (sync)
    {
      cache.Clear();
      foreach (ScriptModule m in modules)
        m.LoadContext.Unload();
      modules.Clear();
    }
  }

  static ScriptScene ReadSettings(ScriptScene s)
  {
    Dictionary<string, object> ctx = s.Context;
    int i = 0;
    double d = 0.0;
    if (Util.TryParse(ctx, PropertyName.CTX_WIDTH, ref i)) s.Width = i;
    if (Util.TryParse(ctx, PropertyName.CTX_HEIGHT, ref i)) s.Height = i;
    if (Util.TryParse(ctx, PropertyName.CTX_SUPERSAMPLING, ref i)) s.SuperSampling = i;
    if (Util.TryParse(ctx, PropertyName.CTX_START_ANIM, ref d)) s.Start = d;
    if (Util.TryParse(ctx, PropertyName.CTX_END_ANIM, ref d)) s.End = d;
    if (Util.TryParse(ctx, PropertyName.CTX_FPS, ref d)) s.Fps = d;
    if (Util.TryParse(ctx, PropertyName.CTX_TIME, ref d)) s.Time = d;
    if (ctx.TryGetValue(PropertyName.CTX_ALGORITHM, out object? alg) && alg is IImageFunction f) s.Algorithm = f;
    if (ctx.TryGetValue(PropertyName.CTX_SYNTHESIZER, out object? syn) && syn is IRenderer r) s.Synthesizer = r;
    if (ctx.TryGetValue(PropertyName.CTX_TOOLTIP, out object? tip) && tip is string t) s.ToolTip = t;
    return s;
  }

  static string Hash(string text) => Convert.ToHexString(SHA256.HashData(Encoding.UTF8.GetBytes(text)));
}
