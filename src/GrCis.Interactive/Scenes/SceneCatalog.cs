using System;
using System.Collections.Generic;
using System.IO;
using GrCis.Hosting;
using GrCis.Scripting;
using Rendering;

namespace GrCis.Interactive;

/// <summary>
/// The scene list of the demo: built-in scenes, every script of a folder (<c>-dir</c>), single
/// script files (<c>-scene</c>, the file picker). Builds the chosen entry into a renderable scene.
/// </summary>
public sealed class SceneCatalog
{
  readonly List<SceneEntry> entries = new();

  /// <param name="scripts">Compiles and runs the scripts (shared by every build, so a script compiles once per content); null = built-in scenes only.</param>
  public SceneCatalog(ScriptHost? scripts = null) => Scripts = scripts;

  /// <summary>Compiles and runs scene scripts; without one, only built-in scenes can be built.</summary>
  public ScriptHost? Scripts { get; set; }

  public IReadOnlyList<SceneEntry> Entries => entries;

  /// <summary>
  /// The script files the front end may open (the studio's: nothing a link leads to outside its folders); null = any.
  /// A refused file of a folder is not listed, a refused single file is an error, and a listed script whose file became
  /// such a link is not built.
  /// </summary>
  public Predicate<string>? AllowScript { get; init; }

  /// <summary>Raised after entries were added.</summary>
  public event EventHandler? Changed;

  /// <summary>Adds a scene made by code: <paramref name="create"/> gets the parameter text.</summary>
  public SceneEntry AddBuiltIn(string name, Func<string, IRayScene> create, string? tooltip = null, string defaultParam = "")
  {
    ArgumentException.ThrowIfNullOrEmpty(name);
    ArgumentNullException.ThrowIfNull(create);
    var entry = new SceneEntry(UniqueName(name), create, tooltip, defaultParam);
    entry.Label = UniqueLabel(entry.Name);
    entries.Add(entry);
    Changed?.Invoke(this, EventArgs.Empty);
    return entry;
  }

  /// <summary>Adds every <c>*.cs</c> file of <paramref name="directory"/>, sorted by name; returns how many were new.</summary>
  public int AddScriptsFolder(string directory)
  {
    ArgumentException.ThrowIfNullOrEmpty(directory);
    if (!Directory.Exists(directory))
      throw new SceneEvaluationException($"{directory}: scripts folder not found.");
    string[] files = Directory.GetFiles(directory, "*.cs");
    Array.Sort(files, StringComparer.OrdinalIgnoreCase);
    int added = 0;
    foreach (string f in files)
      if ((AllowScript == null || AllowScript(f)) && AddScriptCore(f, out _))
        added++;
    if (added > 0)
      Changed?.Invoke(this, EventArgs.Empty);
    return added;
  }

  /// <summary>Adds one script (or returns the entry it already has).</summary>
  public SceneEntry AddScriptFile(string path)
  {
    ArgumentException.ThrowIfNullOrEmpty(path);
    if (!File.Exists(path))
      throw new SceneEvaluationException($"{path}: scene script not found.");
    if (AllowScript != null && !AllowScript(path))
      throw new SceneEvaluationException($"{path}: not allowed here (a link leading outside the folders given).");
    if (AddScriptCore(path, out SceneEntry entry))
      Changed?.Invoke(this, EventArgs.Empty);
    return entry;
  }

  bool AddScriptCore(string path, out SceneEntry entry)
  {
    string full = System.IO.Path.GetFullPath(path);
    foreach (SceneEntry e in entries)
      if (e.Path != null && string.Equals(e.Path, full, StringComparison.Ordinal))
      {
        entry = e;
        return false;
      }
    entry = new SceneEntry(UniqueName(System.IO.Path.GetFileNameWithoutExtension(full)), full);
    entry.Label = UniqueLabel(System.IO.Path.GetFileName(full));
    entries.Add(entry);
    return true;
  }

  /// <summary>The entry called <paramref name="name"/> (case-insensitive), or null.</summary>
  public SceneEntry? Find(string name)
  {
    foreach (SceneEntry e in entries)
      if (string.Equals(e.Name, name, StringComparison.OrdinalIgnoreCase))
        return e;
    return null;
  }

  /// <summary>A catalog holding the classic GrCis scenes (<see cref="BuiltInScenes"/>).</summary>
  public static SceneCatalog WithBuiltInScenes(ScriptHost? scripts = null)
  {
    var catalog = new SceneCatalog(scripts);
    BuiltInScenes.AddTo(catalog);
    return catalog;
  }

  /// <summary>
  /// Adds what a GrCis demo command line names: the built-in scenes unless <c>-nodefault</c>, then
  /// folders, then files. A folder or file that cannot be added is reported in
  /// <paramref name="problems"/> (when given, else thrown) and the rest is still added.
  /// Returns the entry to select first: the first <c>-scene</c> file, else the first script of the folders, else GrCis's
  /// default scene, else the first entry.
  /// </summary>
  public SceneEntry? AddFromCommandLine(DemoCommandLine commandLine, ICollection<string>? problems = null) =>
    AddFromCommandLine(commandLine, c => BuiltInScenes.AddTo(c), problems);

  /// <summary>As <see cref="AddFromCommandLine(DemoCommandLine, ICollection{string}?)"/> with a custom set of built-in scenes.</summary>
  public SceneEntry? AddFromCommandLine(DemoCommandLine commandLine, Action<SceneCatalog>? addBuiltIns, ICollection<string>? problems = null)
  {
    ArgumentNullException.ThrowIfNull(commandLine);
    if (!commandLine.NoDefault)
      addBuiltIns?.Invoke(this);
    foreach (string dir in commandLine.Directories)
      Try(() => AddScriptsFolder(dir), problems);
    SceneEntry? first = null;
    foreach (string file in commandLine.SceneFiles)
      Try(() => first ??= AddScriptFile(file), problems);
    return first ?? entries.Find(e => e.Kind == SceneEntryKind.Script) ?? Find(BuiltInScenes.DefaultName) ?? (entries.Count > 0 ? entries[0] : null);
  }

  static void Try(Action add, ICollection<string>? problems)
  {
    try
    {
      add();
    }
    catch (SceneEvaluationException ex) when (problems != null)
    {
      problems.Add(ex.Message);
    }
  }

  /// <summary>
  /// Builds the scene of <paramref name="entry"/> with <paramref name="param"/> the way <c>grcis render</c> builds it
  /// (<see cref="RenderRequest.Prepare"/>: a script through <see cref="ScriptSceneSource"/>, the one precedence rule,
  /// the scene set to <see cref="RenderSettings.Time"/> or its script's time or its start). The entry then remembers
  /// the script's tooltip and its own values (size, supersampling, animation range) for the UI.
  /// </summary>
  /// <param name="given">The settings the user gave, which win over the script's (<see cref="Precedence"/>).</param>
  /// <param name="start">The animation start the user gave (the script finds it in its context, as with <c>grcis animate --from</c>).</param>
  /// <param name="end">The animation end the user gave.</param>
  /// <param name="fps">The frame rate the user gave.</param>
  /// <exception cref="SceneEvaluationException">The scene could not be built; the message is for the user.</exception>
  public BuiltScene Build(SceneEntry entry, string? param, RenderSettings settings, GivenSettings given = RenderJob.Given,
                          double? start = null, double? end = null, double? fps = null)
  {
    ArgumentNullException.ThrowIfNull(entry);
    ArgumentNullException.ThrowIfNull(settings);
    param ??= "";

    ISceneSource source;
    if (entry.Kind == SceneEntryKind.BuiltIn)
      source = new CatalogSceneSource(entry, param);
    else if (AllowScript != null && !AllowScript(entry.Path!))
      throw new SceneEvaluationException($"{entry.Path}: not allowed here (a link leading outside the folders given).");
    else if (Scripts == null)
      throw new SceneEvaluationException($"{entry.Path}: scene scripts need the script host, and none is configured.");
    else
      source = new ScriptSceneSource(entry.Path!, param, Array.Empty<string>(), Scripts);

    PreparedRender prepared;
    try
    {
      prepared = new RenderRequest(source, settings, given, settings.Time) { Start = start, End = end, Fps = fps }.Prepare();
    }
    catch (Exception ex) when (ex is ScriptCompilationException or ScriptRuntimeException or ScriptChoiceException)
    {
      throw new SceneEvaluationException(ex.Message, ex);
    }
    catch (Exception ex) when (entry.Kind == SceneEntryKind.Script && ex is IOException or UnauthorizedAccessException)
    {
      throw new SceneEvaluationException($"{entry.Path}: cannot read the script ({ex.Message}).", ex);
    }
    catch (Exception ex) when (entry.Kind == SceneEntryKind.BuiltIn && ex is not (SceneEvaluationException or OperationCanceledException or InvalidSettingException))
    {
      throw new SceneEvaluationException($"Scene '{entry.Name}' failed: {ex.Message}", ex);
    }

    ScriptScene? run = prepared.Script;
    var overrides = run == null ? new SceneOverrides() : new SceneOverrides
    {
      Width = run.Width,
      Height = run.Height,
      Supersampling = run.SuperSampling,
      Algorithm = run.Algorithm?.GetType().Name,
      Start = run.Start,
      End = run.End,
      Fps = run.Fps,
    };
    entry.Overrides = overrides;
    if (run?.ToolTip != null)
      entry.Tooltip = run.ToolTip;
    return new BuiltScene(entry, param, prepared) { Overrides = overrides, Tooltip = entry.Tooltip };
  }

  string UniqueLabel(string label)
  {
    string candidate = label;
    for (int k = 2; entries.Exists(e => string.Equals(e.Label, candidate, StringComparison.OrdinalIgnoreCase)); k++)
      candidate = $"{label} ({k})";
    return candidate;
  }

  string UniqueName(string name)
  {
    string candidate = name;
    for (int k = 2; Find(candidate) != null; k++)
      candidate = $"{name} ({k})";
    return candidate;
  }
}
