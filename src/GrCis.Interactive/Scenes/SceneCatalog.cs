using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using Rendering;
using GrCis.Hosting;

namespace GrCis.Interactive;

/// <summary>
/// The scene list of the demo: built-in scenes, every script of a folder (<c>-dir</c>), single
/// script files (<c>-scene</c>, the file picker). Builds the chosen entry into a renderable scene.
/// </summary>
public sealed class SceneCatalog
{
  readonly List<SceneEntry> entries = new();

  public SceneCatalog(IScriptEvaluator? evaluator = null) => Evaluator = evaluator;

  /// <summary>Runs scripts; without one, only built-in scenes can be built.</summary>
  public IScriptEvaluator? Evaluator { get; set; }

  public IReadOnlyList<SceneEntry> Entries => entries;

  /// <summary>Raised after entries were added.</summary>
  public event EventHandler? Changed;

  /// <summary>Adds a scene made by code: <paramref name="create"/> gets the parameter text.</summary>
  public SceneEntry AddBuiltIn(string name, Func<string, IRayScene> create, string? tooltip = null, string defaultParam = "")
  {
    ArgumentException.ThrowIfNullOrEmpty(name);
    ArgumentNullException.ThrowIfNull(create);
    var entry = new SceneEntry(UniqueName(name), create, tooltip, defaultParam);
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
      if (AddScriptCore(f, out _))
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
  public static SceneCatalog WithBuiltInScenes(IScriptEvaluator? evaluator = null)
  {
    var catalog = new SceneCatalog(evaluator);
    BuiltInScenes.AddTo(catalog);
    return catalog;
  }

  /// <summary>
  /// Adds what a GrCis demo command line names: the built-in scenes unless <c>-nodefault</c>, then
  /// folders, then files. A folder or file that cannot be added is reported in
  /// <paramref name="problems"/> (when given, else thrown) and the rest is still added.
  /// Returns the entry to select first: the first <c>-scene</c> file, else GrCis's default scene, else the first entry.
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
    return first ?? Find(BuiltInScenes.DefaultName) ?? (entries.Count > 0 ? entries[0] : null);
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
  /// Builds the scene of <paramref name="entry"/> with <paramref name="param"/>. A script gets the
  /// settings' size, supersampling and time in its context and may override them; the entry then
  /// remembers the tooltip and overrides for the UI.
  /// </summary>
  /// <exception cref="SceneEvaluationException">The scene could not be built; the message is for the user.</exception>
  public BuiltScene Build(SceneEntry entry, string? param, RenderSettings settings)
  {
    ArgumentNullException.ThrowIfNull(entry);
    ArgumentNullException.ThrowIfNull(settings);
    param ??= "";

    if (entry.Kind == SceneEntryKind.BuiltIn)
    {
      IRayScene scene;
      try
      {
        scene = entry.Factory!(param);
      }
      catch (Exception ex) when (ex is not SceneEvaluationException)
      {
        throw new SceneEvaluationException($"Scene '{entry.Name}' failed: {ex.Message}", ex);
      }
      entry.Overrides = new SceneOverrides();
      return new BuiltScene(entry, param, scene) { Tooltip = entry.Tooltip };
    }

    if (Evaluator == null)
      throw new SceneEvaluationException($"{entry.Path}: scene scripts need the script host, and none is configured.");

    string source = entry.ReloadSource();
    var context = new Dictionary<string, object?>
    {
      [PropertyName.CTX_SCENE_NAME] = entry.Name,
      [PropertyName.CTX_SCRIPT_PATH] = entry.Path,
      [PropertyName.CTX_WIDTH] = settings.Width,
      [PropertyName.CTX_HEIGHT] = settings.Height,
      [PropertyName.CTX_SUPERSAMPLING] = settings.SamplesPerPixel,
    };
    if (settings.Time is double t)
      context[PropertyName.CTX_TIME] = t;

    IRayScene target = new DefaultRayScene();
    Evaluator.Run(entry.Path!, source, target, param, context);
    // A script may hand back a scene of its own (e.g. an animated one) instead of filling ours.
    if (context.TryGetValue(PropertyName.CTX_SCENE, out object? sc) && sc is IRayScene own)
      target = own;

    var overrides = new SceneOverrides
    {
      Width = ChangedInt(context, PropertyName.CTX_WIDTH, settings.Width),
      Height = ChangedInt(context, PropertyName.CTX_HEIGHT, settings.Height),
      Supersampling = ChangedInt(context, PropertyName.CTX_SUPERSAMPLING, settings.SamplesPerPixel),
      Start = GetDouble(context, PropertyName.CTX_START_ANIM),
      End = GetDouble(context, PropertyName.CTX_END_ANIM),
      Fps = GetDouble(context, PropertyName.CTX_FPS),
    };
    string? tooltip = context.TryGetValue(PropertyName.CTX_TOOLTIP, out object? tt) ? tt as string : null;
    entry.Overrides = overrides;
    if (tooltip != null)
      entry.Tooltip = tooltip;

    return new BuiltScene(entry, param, target)
    {
      Overrides = overrides,
      Tooltip = tooltip ?? entry.Tooltip,
      ImageFunction = context.TryGetValue(PropertyName.CTX_ALGORITHM, out object? alg) ? alg as IImageFunction : null,
      Renderer = context.TryGetValue(PropertyName.CTX_SYNTHESIZER, out object? syn) ? syn as IRenderer : null,
    };
  }

  string UniqueName(string name)
  {
    string candidate = name;
    for (int k = 2; Find(candidate) != null; k++)
      candidate = $"{name} ({k})";
    return candidate;
  }

  static int? ChangedInt(Dictionary<string, object?> context, string key, int given)
  {
    double? v = GetDouble(context, key);
    if (v == null)
      return null;
    int i = (int)v.Value;
    return i != given ? i : null;
  }

  static double? GetDouble(Dictionary<string, object?> context, string key)
  {
    if (!context.TryGetValue(key, out object? v) || v == null)
      return null;
    return v switch
    {
      IConvertible c when v is not string => c.ToDouble(CultureInfo.InvariantCulture),
      string s when double.TryParse(s, NumberStyles.Float, CultureInfo.InvariantCulture, out double d) => d,
      _ => null,
    };
  }
}
