using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Security.Cryptography;
using System.Text;
using System.Threading;
using GrCis.Scripting.Caching;
using GrCis.Scripting.Compilation;
using Rendering;
using Utilities;

namespace GrCis.Scripting;

/// <summary>
/// Compiles and runs GrCis scene scripts. A script is compiled once per (path, content, modules) and
/// cached (least recently used entries are evicted and their code unloaded); every further run, on any
/// thread, executes the compiled code. With a <see cref="ScriptCache"/> the compiled code is also kept on
/// disk, and a later process loads it instead of compiling. Thread-safe.
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
  /// Compile script and module code with optimisations: classes declared in scripts and modules (textures,
  /// cameras, solids, tracers) run faster, but the JIT may inline their methods, and then a runtime error or
  /// a failed assertion cannot always name its line. Off by default: readable errors first, as a student's
  /// Debug build.
  /// </param>
  /// <param name="diskCache">
  /// Where compiled scripts and modules are kept between processes (see <see cref="ScriptCache"/>; front ends pass
  /// <see cref="ScriptCache.FromEnvironment"/>); null compiles every script of a new process afresh.
  /// </param>
  public ScriptHost(int cacheCapacity = DefaultCacheCapacity, bool optimizeScripts = false, ScriptCache? diskCache = null)
  {
    DiskCache = diskCache;
    // Modules are built with DEBUG defined: a failed Debug.Assert must warn, not end the process.
    Assertions.Install();
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

  /// <summary>The compiled-script cache on disk this host reads and fills (null: none).</summary>
  public ScriptCache? DiskCache { get; }

  /// <summary>
  /// Called on the compiling thread before each compilation of a script or module this host performs (not when either
  /// cache has it): a front end can start what only a compiling run needs. <c>grcis</c> starts the multicore JIT profile of
  /// the compiler there, which a run that finds its script compiled never loads.
  /// </summary>
  public Action? BeforeCompile { get; init; }

  /// <summary>Number of script compilations this host has performed (hits of either cache do not count).</summary>
  public int CompilationCount => Volatile.Read(ref compilations);

  /// <summary>Number of module compilations this host has performed (modules loaded from the disk cache do not count).</summary>
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
  public ScriptModule AddModule(string directory) => AddModules(new[] { directory });

  /// <summary>
  /// Compiles the folders together into one module assembly, as one project of the student's would have
  /// built them: their classes may use each other, in any direction (see <see cref="AddModule"/> for
  /// which files count). Adding the same unchanged folders again is a no-op.
  /// </summary>
  /// <exception cref="DirectoryNotFoundException">A folder does not exist.</exception>
  /// <exception cref="ScriptCompilationException">A folder holds no classes, or a module file did not compile.</exception>
  public ScriptModule AddModules(IEnumerable<string> directories)
  {
    ArgumentNullException.ThrowIfNull(directories);
    var dirs = new List<string>();
    foreach (string directory in directories)
    {
      ArgumentException.ThrowIfNullOrEmpty(directory);
      string dir = Path.GetFullPath(directory);
      if (!Directory.Exists(dir))
        throw new DirectoryNotFoundException($"Module folder not found: '{dir}'");
      if (!dirs.Contains(dir))
        dirs.Add(dir);
    }
    if (dirs.Count == 0)
      throw new ArgumentException("No module folder given.", nameof(directories));

    // Every *.cs file outside build output, read once: which of them are scene scripts is decided by their text.
    var texts = new Dictionary<string, string>(StringComparer.Ordinal);
    var candidates = new List<ModuleFiles.Candidate>();
    foreach (string dir in dirs)
      foreach (string file in ModuleFiles.Candidates(dir))
      {
        if (!texts.TryGetValue(file, out string? text))
          texts[file] = text = File.ReadAllText(file);
        candidates.Add(new ModuleFiles.Candidate(dir, file, text));
      }

    lock (sync)
    {
      string contentHash = CacheKeys.ModuleContent(candidates);
      ScriptModule? existing = modules.FirstOrDefault(m => m.ContentHash == contentHash);
      if (existing != null)
        return existing;
      ScriptModule[] earlier = modules.ToArray();
      string key = CacheKeys.Module(contentHash, earlier, OptimizeScripts);
      (ScriptModule module, bool compiled) = CachedBuilds.Module(DiskCache, dirs, candidates, contentHash, key, earlier, OptimizeScripts, BeforeCompile);
      if (compiled)
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
  public CompiledScript CompileSource(string source, string path) => CompileSource(source, path, DiskCache);

  /// <summary>
  /// The compiler's errors and warnings for script text, without running it (an editor's check as the user types). The
  /// compilation is kept in memory, so running the same text next reuses it, but not written to the disk cache: a checked
  /// text is mostly a draft.
  /// </summary>
  public IReadOnlyList<ScriptDiagnostic> Check(string source, string path)
  {
    try
    {
      return CompileSource(source, path, disk: null).Warnings;
    }
    catch (ScriptCompilationException e)
    {
      return e.Diagnostics;
    }
  }

  CompiledScript CompileSource(string source, string path, ScriptCache? disk)
  {
    ArgumentNullException.ThrowIfNull(source);
    ArgumentException.ThrowIfNullOrEmpty(path);
    string full = Path.GetFullPath(path);

    Lazy<CompiledScript> entry;
    string key;
    lock (sync)
    {
      ScriptModule[] mods = modules.ToArray();
      key = Hash(full + "\0" + source + "\0" + string.Join("|", mods.Select(m => m.CacheKey)));
      if (!cache.TryGet(key, out entry))
      {
        string memoryKey = key;
        entry = new Lazy<CompiledScript>(() =>
        {
          (CompiledScript script, bool compiled) = CachedBuilds.Script(disk, full, source, memoryKey, mods, OptimizeScripts, BeforeCompile);
          if (compiled)
            Interlocked.Increment(ref compilations);
          return script;
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
  public ScriptScene Load(string path, string? param = null, Dictionary<string, object>? context = null, ScriptContextInit? init = null) =>
    Run(Compile(path), param, context, null, init);

  /// <summary>
  /// Runs a compiled script with GrCis's context protocol. First the context is filled as GrCis's
  /// <c>Scripts.ContextInit</c> filled it (scene name, size, supersampling, animation range; see
  /// <see cref="ScriptContextInit"/>). When <paramref name="context"/> held fewer than two entries, the
  /// script is first called with <c>Preprocessing = true</c> (and a throw-away scene): it may simulate once,
  /// store results in a free context key and <c>return;</c>. Then the regular call fills
  /// <paramref name="scene"/> (a new <see cref="DefaultRayScene"/> by default).
  /// </summary>
  /// <param name="init">
  /// The values a script finds in the context: given, they replace what the context holds (GrCis refilled
  /// them before every call); null fills only the keys the context lacks, with GrCis's defaults. A value the
  /// script writes is its choice (a setting of the returned <see cref="ScriptScene"/>); a value it leaves
  /// alone is not, even when it read it.
  /// </param>
  /// <exception cref="ScriptRuntimeException">The script threw; the message names its line.</exception>
  public ScriptScene Run(CompiledScript script, string? param = null, Dictionary<string, object>? context = null, IRayScene? scene = null,
                         ScriptContextInit? init = null)
  {
    ArgumentNullException.ThrowIfNull(script);
    context ??= new Dictionary<string, object>();
    bool preprocess = context.Count < 2;
    context[PropertyName.CTX_SCRIPT_PATH] = script.Path;
    Dictionary<string, object> filled = FillContext(context, init, script.Path);

    if (preprocess)
    {
      context[PropertyName.CTX_PREPROCESSING] = true;
      // A throw-away scene of the kind the regular call gets: scripts older than the preprocessing call
      // (May 2020) treat every call as the regular one and may cast the scene to ITimeDependent.
      DefaultRayScene scratch = scene is AnimatedRayScene ? new AnimatedRayScene() : new DefaultRayScene();
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

    return ReadSettings(new ScriptScene(script, scene, context, preprocess), filled);
  }

  /// <summary>
  /// Writes the values of <paramref name="init"/> (all of them), or GrCis's defaults where the context lacks
  /// a key (no <paramref name="init"/>); returns the very objects written, so a script's own writes can be
  /// told from them afterwards.
  /// </summary>
  static Dictionary<string, object> FillContext(Dictionary<string, object> context, ScriptContextInit? init, string path)
  {
    bool replace = init != null;
    init ??= ScriptContextInit.Default;
    var filled = new Dictionary<string, object>(7);
    void Put(string key, object value)
    {
      if (replace || !context.ContainsKey(key))
        filled[key] = context[key] = value;
    }
    Put(PropertyName.CTX_SCENE_NAME, init.SceneName ?? System.IO.Path.GetFileName(path));
    Put(PropertyName.CTX_WIDTH, init.Width);
    Put(PropertyName.CTX_HEIGHT, init.Height);
    Put(PropertyName.CTX_SUPERSAMPLING, init.SuperSampling);
    Put(PropertyName.CTX_START_ANIM, init.Start);
    Put(PropertyName.CTX_END_ANIM, init.End);
    Put(PropertyName.CTX_FPS, init.Fps);
    return filled;
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

  /// <summary>The script's choices: the settings it wrote, not those the host filled in (<paramref name="filled"/>).</summary>
  static ScriptScene ReadSettings(ScriptScene s, Dictionary<string, object> filled)
  {
    Dictionary<string, object> ctx = s.Context;
    bool Chosen(string key) =>
      ctx.TryGetValue(key, out object? value) && !(filled.TryGetValue(key, out object? ours) && ReferenceEquals(value, ours));
    int i = 0;
    double d = 0.0;
    if (Chosen(PropertyName.CTX_WIDTH) && KeyValueText.TryParse(ctx, PropertyName.CTX_WIDTH, ref i)) s.Width = i;
    if (Chosen(PropertyName.CTX_HEIGHT) && KeyValueText.TryParse(ctx, PropertyName.CTX_HEIGHT, ref i)) s.Height = i;
    if (Chosen(PropertyName.CTX_SUPERSAMPLING) && KeyValueText.TryParse(ctx, PropertyName.CTX_SUPERSAMPLING, ref i)) s.SuperSampling = i;
    if (Chosen(PropertyName.CTX_START_ANIM) && KeyValueText.TryParse(ctx, PropertyName.CTX_START_ANIM, ref d)) s.Start = d;
    if (Chosen(PropertyName.CTX_END_ANIM) && KeyValueText.TryParse(ctx, PropertyName.CTX_END_ANIM, ref d)) s.End = d;
    if (Chosen(PropertyName.CTX_FPS) && KeyValueText.TryParse(ctx, PropertyName.CTX_FPS, ref d)) s.Fps = d;
    if (KeyValueText.TryParse(ctx, PropertyName.CTX_TIME, ref d)) s.Time = d;
    if (ctx.TryGetValue(PropertyName.CTX_ALGORITHM, out object? alg) && alg is IImageFunction f) s.Algorithm = f;
    if (ctx.TryGetValue(PropertyName.CTX_SYNTHESIZER, out object? syn) && syn is IRenderer r) s.Synthesizer = r;
    if (ctx.TryGetValue(PropertyName.CTX_TOOLTIP, out object? tip) && tip is string t) s.ToolTip = t;
    return s;
  }

  static string Hash(string text) => Convert.ToHexString(SHA256.HashData(Encoding.UTF8.GetBytes(text)));
}
