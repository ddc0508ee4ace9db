using System;
using System.Collections.Generic;
using System.Threading;
using System.Threading.Tasks;
using Rendering;
using Rendering.Execution;
using GrCis.Hosting;

namespace GrCis.Interactive;

/// <summary>
/// Everything behind the demo window, for any front end to bind to: the scene list and selection,
/// parameters, settings, render/stop with previews, the pixel probe, extra views, history, saving,
/// animation, and re-rendering when the selected script changes on disk.
/// </summary>
public sealed partial class DemoController : IDisposable
{
  readonly object sync = new();
  RenderSession? session;
  CancellationTokenSource? build;
  CancellationTokenSource? inspecting;
  Task? buildTask;
  ScriptWatcher? watcher;
  SceneEntry? selected;
  bool watch;
  // The render asked for last (events of a replaced one are ignored) and whether its scene is being built.
  long renderId;
  bool building;
  // The last render whose completion was raised: done for the page even while its session winds down.
  long finishedId;

  public DemoController(SceneCatalog catalog) => Catalog = catalog ?? throw new ArgumentNullException(nameof(catalog));

  public SceneCatalog Catalog { get; }

  /// <summary>From <c>-render-to FILE</c>: the window renders the selected scene at start, saves it here and closes.</summary>
  public string? RenderTo { get; init; }

  public RenderSettings Settings { get; set; } = new();

  /// <summary>
  /// Which of <see cref="Settings"/> the user gave, winning over the script's own values by the one precedence rule
  /// (<see cref="Precedence"/>), exactly as options typed on the command line do; the rest are the script's when it
  /// sets them. None by default, so an untouched window renders what <c>grcis render</c> renders; a front end marks a
  /// setting once the user changes its field (<see cref="GivenSettings.Size"/>, <see cref="GivenSettings.SamplesPerPixel"/>,
  /// <see cref="GivenSettings.Shadows"/>, …). A chosen <see cref="Algorithm"/> is always given.
  /// </summary>
  public GivenSettings Given { get; set; }

  /// <summary>
  /// The image function chosen in the demo, replacing the script's own (CTX_ALGORITHM) as <c>grcis render --algorithm</c>
  /// does; null = the scene's choice: the script's function, else <see cref="RenderSettings.Algorithm"/>.
  /// </summary>
  public RenderAlgorithm? Algorithm { get; set; }

  /// <summary>
  /// Render in passes that add samples to every pixel (<see cref="RenderSession.Progressive"/>) rather than tile by tile;
  /// null = automatic: in passes for the Monte Carlo algorithms (distributed ray tracing, path tracing), whose images
  /// are worth watching converge. The final image is the same either way.
  /// </summary>
  public bool? Progressive { get; set; }

  public RenderHistory History { get; } = new();

  /// <summary>Where events are raised (the UI thread's context); null = whichever thread produced them.</summary>
  public SynchronizationContext? EventContext { get; set; }

  /// <summary>Preview cadence handed to each session.</summary>
  public TimeSpan PreviewInterval { get; set; } = TimeSpan.FromMilliseconds(500);

  /// <summary>How long a new render waits for a stopped script to unwind before running without it.</summary>
  public TimeSpan AbandonStuckScriptAfter { get; set; } = TimeSpan.FromSeconds(2);

  /// <summary>Debounce of the script watcher.</summary>
  public TimeSpan WatchDebounce { get; set; } = TimeSpan.FromMilliseconds(300);

  /// <summary>The job of the last render started (what the probe and extra views use).</summary>
  public RenderJob? LastJob { get; private set; }

  public RenderResult? LastResult { get; private set; }

  public bool IsRendering
  {
    get
    {
      lock (sync)
        return session?.IsRunning ?? false;
    }
  }

  /// <summary>True while the last render asked for builds its scene or renders (what a status line shows); false after Stop.</summary>
  public bool IsBusy
  {
    get
    {
      lock (sync)
        return BusyLocked;
    }
  }

  /// <summary><see cref="IsBusy"/>, read under <c>sync</c>.</summary>
  bool BusyLocked => building || (session?.IsRunning == true && finishedId != renderId);

  /// <summary>True while the last render asked for builds its scene (compiles and runs its script), before its pixels; false after Stop.</summary>
  public bool IsBuilding
  {
    get
    {
      lock (sync)
        return building;
    }
  }

  /// <summary>The number of the render asked for last (<see cref="RenderAsync"/>, a watched script's change); its events are the only ones raised.</summary>
  public long RenderId => Interlocked.Read(ref renderId);

  /// <summary>
  /// Memory the renders may use, in bytes; null = what this process may use (<see cref="ImageMemory.Available"/>). A size
  /// that does not fit is refused before any work, as <c>grcis render</c> refuses it.
  /// </summary>
  public long? MemoryLimit { get; set; }

  /// <summary>
  /// Images of the render's size the window holds at its peak, for the memory check: the framebuffer, the preview and
  /// noise buffers and their 8-bit copies (a 16384x16384 render in the studio was measured at about 22 GB, 82 bytes a
  /// pixel: five of <see cref="ImageMemory.BytesPerPixel"/>).
  /// </summary>
  public const int ImagesHeld = 5;

  public SceneEntry? Selected
  {
    get => selected;
    set
    {
      selected = value;
      RestartWatcher();
    }
  }

  /// <summary>Re-render whenever the selected script's file changes.</summary>
  public bool WatchScript
  {
    get => watch;
    set
    {
      watch = value;
      RestartWatcher();
    }
  }

  /// <summary>
  /// The scene of the render asked for last was built and its render has started (its first previews may come before this).
  /// Like every event of the controller, raised with none of its locks held, so a handler may read its state.
  /// </summary>
  public event EventHandler<BuiltScene>? SceneEvaluated;

  public event EventHandler<RenderPreviewEventArgs>? PreviewReady;

  public event EventHandler<RenderProgressEventArgs>? ProgressChanged;

  public event EventHandler<RenderCompletedEventArgs>? RenderCompleted;

  /// <summary>A message for the user (script error, save failure; no stack traces) with the script places it is about.</summary>
  public event EventHandler<DemoErrorEventArgs>? Error;

  /// <summary>Raised when a watched script changed on disk, just before the re-render starts.</summary>
  public event EventHandler<ScriptChangedEventArgs>? ScriptChanged;

  /// <summary>
  /// Raised when a render is asked for (<see cref="RenderAsync"/>, a watched script's change) once it has its number
  /// (<see cref="RenderId"/>, the argument) and is busy building: a front end told of changes rather than polling learns here
  /// that the work on show is a new one.
  /// </summary>
  public event EventHandler<long>? RenderStarted;

  /// <summary>
  /// Builds the selected scene with its parameter text and renders it, stopping any build or render in
  /// progress. The script runs on a worker thread, so a slow or stuck script never blocks the caller's
  /// (UI) thread, and <see cref="Stop"/> ends it (see <see cref="Interruption"/>). Returns the result, or
  /// null when the scene could not be built (see <see cref="Error"/>) or the build was stopped.
  /// </summary>
  public Task<RenderResult?> RenderAsync() => StartRender().Rendering;

  /// <summary>
  /// As <see cref="RenderAsync"/>, returning with the task the number this render was given. Read
  /// <see cref="RenderId"/> after the call instead and a render asked for at the same time may already have
  /// replaced it.
  /// </summary>
  public (long Id, Task<RenderResult?> Rendering) StartRender()
  {
    SceneEntry entry;
    RenderSettings settings;
    GivenSettings given;
    try
    {
      entry = Selected ?? throw new InvalidOperationException("Choose a scene first.");
      (settings, given) = Requested(Settings);
    }
    catch (Exception e)
    {
      // As from an async method: the refusal is the task's, and no new number was given.
      return (RenderId, Task.FromException<RenderResult?>(e));
    }
    CancellationTokenSource building;
    Task? previous;
    long id;
    lock (sync)
    {
      id = ++renderId;
      this.building = true;
      session?.Stop();
      build?.Cancel();
      building = build = new CancellationTokenSource();
      previous = buildTask;
    }
    Raise(RenderStarted, id);
    return (id, Run());

    async Task<RenderResult?> Run()
    {
      try
      {
        return await RenderAsync(id, entry, settings, given, building, previous).ConfigureAwait(false);
      }
      finally
      {
        BuildEnded(id);
      }
    }
  }

  void BuildEnded(long id)
  {
    lock (sync)
      if (id == renderId)
        building = false;
  }

  async Task<RenderResult?> RenderAsync(long id, SceneEntry entry, RenderSettings settings, GivenSettings given, CancellationTokenSource building, Task? previous)
  {
    // Let a stopped script unwind before the next one runs (it may hold files or state of its own); one that
    // ignores the stop (a sleep, not a loop) is left behind after a while rather than blocking the demo.
    if (previous != null)
      await Task.WhenAny(previous, Task.Delay(AbandonStuckScriptAfter)).ConfigureAwait(false);

    BuiltScene built;
    RenderJob job;
    try
    {
      Task<(BuiltScene, RenderJob)> task = Task.Factory.StartNew(() =>
      {
        using Interruption.Scope interruption = Interruption.Use(building.Token);
        BuiltScene b = Catalog.Build(entry, entry.ParameterText, settings, given);
        return (b, b.ToJob());
      }, building.Token, TaskCreationOptions.LongRunning, TaskScheduler.Default);
      lock (sync)
        buildTask = task;
      (built, job) = await task.ConfigureAwait(false);
    }
    catch (OperationCanceledException) when (building.IsCancellationRequested)
    {
      return null;
    }
    catch (Exception ex) when (ex is SceneEvaluationException or ArgumentException)
    {
      // Not busy any more when the message arrives (a window enables Render again on it).
      BuildEnded(id);
      if (!building.IsCancellationRequested)
        Raise(Error, DemoErrorEventArgs.For(ex.Message, ex));
      return null;
    }

    // Refused before any work when it cannot fit, as grcis render refuses it.
    if (ImageMemory.Shortfall(job.Width, job.Height, ImagesHeld, MemoryLimit, oneImage: true) is string shortfall)
    {
      BuildEnded(id);
      if (!building.IsCancellationRequested)
        Raise(Error, DemoErrorEventArgs.For($"{shortfall}; choose a smaller size (a render here holds its previews and noise estimate too)", null));
      return null;
    }

    RenderSession s;
    lock (sync)
    {
      // Stopped, or another render started, while the script ran.
      if (building.IsCancellationRequested)
        return null;
      this.building = false;
      LastJob = job;
      s = session = new RenderSession(job)
      {
        PreviewInterval = PreviewInterval,
        EventContext = EventContext,
        Progressive = Progressive ?? IsMonteCarlo(job.ImageFunction),
      };
      // A render replaced by a newer one (Render again, a watched script saved) says nothing more.
      s.PreviewReady += (_, e) =>
      {
        if (id == RenderId)
          PreviewReady?.Invoke(this, e);
      };
      s.ProgressChanged += (_, e) =>
      {
        if (id == RenderId)
          ProgressChanged?.Invoke(this, e);
      };
      s.Completed += (_, e) =>
      {
        lock (sync)
        {
          if (id != renderId)
            return;
          finishedId = id;
        }
        // On the UI context when one is set, so history and the display change together.
        LastResult = e.Result;
        // A failed render's image (black, or cut short) is nothing to go back to.
        if (e.Result.Error == null)
          History.Add(RenderRecord.From(e.Result));
        // A script's or module's error already names its place (file(line,col): runtime error: …), as grcis prints it.
        if (e.Result.Error != null)
          Error?.Invoke(this, DemoErrorEventArgs.For(e.Result.Error is GrCis.Scripting.ScriptRuntimeException located
            ? located.Message : $"Rendering failed: {e.Result.Error.Message}", e.Result.Error));
        RenderCompleted?.Invoke(this, e);
      };
      s.Start();
    }
    // Raised with no lock held, as every event here: a front end that reads the state (IsBusy) under a lock of its own,
    // a lock its handler takes too, would otherwise deadlock with us (the studio's status and its event handlers).
    if (id == RenderId)
      Raise(SceneEvaluated, built);
    return await s.Task.ConfigureAwait(false);
  }

  /// <summary>Image functions whose samples differ in more than the pixel position: noise that passes show converging.</summary>
  static bool IsMonteCarlo(Rendering.IImageFunction function) =>
    function is Rendering.PathTracing or Rendering.Distributed.DistributedRayTracing;

  /// <summary>Stops the script being evaluated and the render in progress (finished tiles are kept).</summary>
  public void Stop()
  {
    lock (sync)
    {
      stoppedBuild = buildTask;
      stoppedSession = session;
      build?.Cancel();
      inspecting?.Cancel();
      session?.Stop();
      building = false;   // a script that ignores the stop is left behind (see AbandonStuckScriptAfter)
      finishedId = renderId;   // idle at once, even while a stuck script's texture keeps the session winding down
    }
  }

  /// <summary>Why <see cref="ComputeExtraViews"/> refuses while a render runs (the studio answers a request with it too).</summary>
  public const string ExtraViewsNeedIdle = "Wait for the render to finish (or stop it) before computing the extra views.";

  /// <summary>Depth, normal and ray maps of the last render (after it finished).</summary>
  public ExtraViews ComputeExtraViews(CancellationToken cancel = default)
  {
    RenderJob job = LastJob ?? throw new InvalidOperationException("Render something first.");
    if (IsRendering)
      throw new InvalidOperationException(ExtraViewsNeedIdle);
    // The noise map is the last render's own estimate, when that render was of this job.
    NoiseImage? noise = LastResult is RenderResult r && ReferenceEquals(r.Job, job) ? r.Frame.Noise : null;
    return ExtraViews.Compute(job, cancel, noise);
  }

  /// <summary>Saves the current history image; reports a failure through <see cref="Error"/> and returns false.</summary>
  public bool SaveImage(string path)
  {
    try
    {
      History.SaveCurrent(path);
      return true;
    }
    catch (Exception ex) when (ex is Rendering.Imaging.ImageSaveException or InvalidOperationException or ArgumentException)
    {
      Raise(Error, DemoErrorEventArgs.For(ex.Message, null));
      return false;
    }
  }

  /// <summary>
  /// An animation run of the selected scene as <c>grcis animate</c> renders it: start, end and frame rate each as given
  /// here, else the script's, else the scene's own range, else 0 to 10 s at 25 fps (<see cref="AnimationRange"/>).
  /// </summary>
  /// <exception cref="SceneEvaluationException">The scene could not be built.</exception>
  /// <exception cref="ArgumentOutOfRangeException">The range is impossible (end before start, fps not positive).</exception>
  /// <exception cref="InvalidSettingException">The size does not fit in memory (<see cref="MemoryLimit"/>).</exception>
  public AnimationRun CreateAnimation(double? start = null, double? end = null, double? fps = null)
  {
    SceneEntry entry = Selected ?? throw new InvalidOperationException("Choose a scene first.");
    (RenderSettings settings, GivenSettings given) = Requested(Settings with { Time = null });
    BuiltScene built = Catalog.Build(entry, entry.ParameterText, settings, given, start, end, fps);
    (double s, double e, double f) = AnimationRange.Resolve(start, end, fps, built.Prepared.Timing, built.Prepared.Scene);
    RenderJob job = built.ToJob();
    // One frame at a time, each with its 8-bit copy (what grcis animate holds per frame, and a frame kept to show).
    if (ImageMemory.Shortfall(job.Width, job.Height, 2, MemoryLimit, oneImage: true) is string shortfall)
      throw new InvalidSettingException(Setting.Size, $"{job.Width}x{job.Height}", shortfall + "; choose a smaller size");
    return new AnimationRun(job, new AnimationTimeline(s, e, f));
  }

  // A chosen algorithm is a given setting, so the one precedence rule replaces the script's function with it.
  (RenderSettings, GivenSettings) Requested(RenderSettings settings) =>
    Algorithm is RenderAlgorithm a
      ? (settings with { Algorithm = a }, Given | GivenSettings.Algorithm)
      : (settings, Given & ~GivenSettings.Algorithm);

  void RestartWatcher()
  {
    lock (sync)
    {
      watcher?.Dispose();
      watcher = null;
      if (!watch || selected?.Path == null)
        return;
      watcher = new ScriptWatcher(selected.Path, WatchDebounce);
      watcher.Changed += (_, e) =>
      {
        Raise(ScriptChanged, e);
        _ = RenderAsync();
      };
    }
  }

  void Raise<T>(EventHandler<T>? handler, T args) => EventContext.Raise(handler, this, args);

  public void Dispose()
  {
    lock (sync)
    {
      watcher?.Dispose();
      watcher = null;
      build?.Cancel();
    }
    RenderSession? s;
    lock (sync)
      s = session;
    s?.Dispose();
  }
}
