using System;
using System.Collections.Generic;
using System.IO;
using GrCis.Scripting;
using GrCis.Scripting.Caching;
using Rendering;

namespace GrCis.Hosting;

/// <summary>
/// A GrCis scene script (<c>*.cs</c>): compiled once by a <see cref="ScriptHost"/> (with the modules
/// given by <c>--module</c>) and run with GrCis's context protocol. The script gets an
/// <see cref="AnimatedRayScene"/>, as in GrCis's animation-capable front ends, so
/// <c>scene is ITimeDependent</c> lets it animate; a still script never notices. Every front end (the CLI, the
/// demo window, the studio) builds a script's scene through this class.
/// </summary>
public sealed class ScriptSceneSource : ISceneSource, IDisposable
{
  readonly ScriptHost host;
  readonly bool ownsHost;
  readonly IReadOnlyList<string> modules;
  bool modulesLoaded;

  /// <param name="path">Full path of an existing script file.</param>
  /// <param name="param">The <c>--param</c> text passed to the script as <c>param</c>.</param>
  /// <param name="modules">Full paths of existing module folders, in the order given.</param>
  public ScriptSceneSource(string path, string? param, IReadOnlyList<string> modules) : this(path, param, modules, (ScriptCache?)null)
  {
  }

  /// <param name="path">Full path of an existing script file.</param>
  /// <param name="param">The text passed to the script as <c>param</c>.</param>
  /// <param name="modules">Full paths of existing module folders, in the order given.</param>
  /// <param name="host">
  /// A host shared with other sources, which keeps compiled scripts between them (a window or a page builds a new
  /// source per render); null = one of its own, disposed with the source.
  /// </param>
  public ScriptSceneSource(string path, string? param, IReadOnlyList<string> modules, ScriptHost? host)
    : this(path, param, modules, host ?? new ScriptHost(cacheCapacity: 4), ownsHost: host == null)
  {
  }

  /// <param name="path">Full path of an existing script file.</param>
  /// <param name="param">The text passed to the script as <c>param</c>.</param>
  /// <param name="modules">Full paths of existing module folders, in the order given.</param>
  /// <param name="diskCache">The compiled-script cache the source's own host reads and fills (null: none).</param>
  /// <param name="beforeCompile">The host's <see cref="ScriptHost.BeforeCompile"/>.</param>
  public ScriptSceneSource(string path, string? param, IReadOnlyList<string> modules, ScriptCache? diskCache, Action? beforeCompile = null)
    : this(path, param, modules, new ScriptHost(cacheCapacity: 4, diskCache: diskCache) { BeforeCompile = beforeCompile }, ownsHost: true)
  {
  }

  ScriptSceneSource(string path, string? param, IReadOnlyList<string> modules, ScriptHost host, bool ownsHost)
  {
    Path = path;
    Param = param ?? "";
    this.modules = modules;
    this.ownsHost = ownsHost;
    this.host = host;
  }

  /// <summary>Full path of the script.</summary>
  public string Path { get; }

  /// <summary>Parameter text handed to the script.</summary>
  public string Param { get; }

  public string DisplayName => System.IO.Path.GetFileName(Path);

  public string OutputStem => Slug.Of(System.IO.Path.GetFileNameWithoutExtension(Path));

  /// <summary>The compiled script (after the first <see cref="Load"/>).</summary>
  public CompiledScript? Script { get; private set; }

  /// <summary>
  /// Compiles the script as it is on disk now (the host compiles a content once) and runs it on a fresh context:
  /// preprocessing call, then the regular one.
  /// </summary>
  /// <param name="init">What the script finds in its context (the front end's values); null = GrCis's defaults.</param>
  /// <exception cref="FileNotFoundException">The script file is gone.</exception>
  /// <exception cref="ScriptCompilationException">The script or a module did not compile.</exception>
  /// <exception cref="ScriptRuntimeException">The script threw; names its line.</exception>
  public ScriptScene Load(ScriptContextInit? init = null)
  {
    if (!modulesLoaded)
    {
      // All --module folders of one render are one assembly, as one project of the student's.
      if (modules.Count > 0)
        host.AddModules(modules);
      modulesLoaded = true;
    }
    Script = host.Compile(Path);
    init ??= ScriptContextInit.Default;
    return host.Run(Script, Param, new Dictionary<string, object>(), new AnimatedRayScene(),
                    init.SceneName == null ? init with { SceneName = DisplayName } : init);
  }

  public IRayScene CreateScene() => Load().Scene;

  /// <summary>
  /// An exception from rendering (thrown by a class the script declared) with the script line that threw,
  /// or the exception itself when the script is not on its stack.
  /// </summary>
  public Exception WithScriptLine(Exception e) => Script?.FindScriptLine(e) ?? e;

  public void Dispose()
  {
    if (ownsHost)
      host.Dispose();
  }
}
