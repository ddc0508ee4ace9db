using System;
using System.Collections.Generic;
using System.Threading;
using System.Threading.Tasks;
using GrCis.Hosting;
using GrCis.Interactive;
using Rendering.Imaging;

namespace GrCis.Studio;

/// <summary>
/// The demo's logic (<see cref="DemoController"/>) as the page sees it: the latest image (a preview while
/// rendering, the final image after), a version number that changes with it, and the state of the render.
/// Every change is announced (<see cref="NextChange"/>), so the event stream (<see cref="StudioEvents"/>) pushes it to the
/// page, which fetches the image when its version changes; <see cref="Status"/> is the whole state at once.
/// </summary>
public sealed class StudioSession : IDisposable
{
  readonly object sync = new();

  /// <summary>Held while one render request sets the controller up and starts it.</summary>
  readonly object starting = new();
  FloatImage? image;
  double gamma = 1.0;
  int version;
  double fraction;
  TimeSpan elapsed;
  string? error;
  string statistics = "";
  int? samples;
  double? noise;
  IReadOnlyList<ScriptError> diagnostics = Array.Empty<ScriptError>();
  // How far the render had got when the user stopped it: what its progress stays at (its last tiles or pass, still
  // finishing, report more, and its completion 100 %); null while not stopped.
  double? stoppedAt;
  // The scene whose script the diagnostics are in (the render's, or a saved script's being checked).
  string? diagnosticsScene;
  // A saved script other than the watched one being compiled (Check); its number, so a stopped or replaced check says nothing.
  bool checking;
  long checkId;
  // The last check that ran to its end (not stopped, not replaced): the page learns from it that its save compiled.
  long checkedId;
  // What the event stream tells apart (StudioEvents): a change of the error or diagnostics (set or cleared), and a
  // render's completion (how many so far, the last one's number, whether it was stopped).
  long errorSequence;
  long completions;
  long completedId;
  bool cancelled;
  // Completed at the next change and replaced: whoever waits on it learns of the change (NextChange).
  TaskCompletionSource changed = new(TaskCreationOptions.RunContinuationsAsynchronously);
  int streams;

  public StudioSession(DemoController controller)
  {
    Controller = controller ?? throw new ArgumentNullException(nameof(controller));
    // At least two previews a second while tiles come in.
    Controller.PreviewInterval = TimeSpan.FromMilliseconds(250);
    // A script saved by the page or by another editor re-renders (see the source endpoint).
    Controller.WatchDebounce = TimeSpan.FromMilliseconds(100);
    Controller.WatchScript = true;
    Controller.ScriptChanged += (_, _) => Started();
    Controller.RenderStarted += (_, _) => Changed();
    Controller.SceneEvaluated += (_, _) => Changed();
    Controller.PreviewReady += (_, e) =>
    {
      if (e.Samples != null)
        lock (sync)
        {
          samples = e.Samples;
          noise = e.Noise;
        }
      Show(e.Image, e.Gamma, e.Fraction);
    };
    Controller.ProgressChanged += (_, e) =>
    {
      lock (sync)
      {
        fraction = stoppedAt ?? e.Fraction;
        elapsed = e.Elapsed;
      }
      Changed();
    };
    Controller.RenderCompleted += (_, e) =>
    {
      lock (sync)
      {
        statistics = e.Result.Statistics.ToString();
        samples = e.Result.Cancelled ? samples : e.Result.Statistics.SamplesPerPixel;
        noise = e.Result.Cancelled ? noise : e.Result.Statistics.Noise;
        // The controller raises only the completion of the render asked for last: this one.
        completions++;
        completedId = Controller.RenderId;
        cancelled = e.Result.Cancelled;
      }
      Show(e.Result.Image, e.Result.Gamma, 1.0);
    };
    Controller.Error += (_, e) =>
    {
      lock (sync)
      {
        error = e.Message;
        diagnostics = ScriptErrors.In(e.Diagnostics, Controller.Selected?.Path);
        diagnosticsScene = Controller.Selected?.Name;
        errorSequence++;
      }
      Changed();
    };
  }

  /// <summary>The error the page shows until the first render (the supervisor's sentence on why this studio was restarted).</summary>
  public string? Notice
  {
    init
    {
      error = value;
      errorSequence++;
    }
  }

  /// <summary>Which studio process this is (<see cref="StudioOptions.Generation"/>), in every status.</summary>
  public int Generation { get; init; }

  public DemoController Controller { get; }

  /// <summary>Starts rendering <paramref name="entry"/> with <paramref name="param"/> and <paramref name="settings"/>, stopping any render in progress.</summary>
  /// <param name="algorithm">The image function replacing the script's (<see cref="DemoController.Algorithm"/>); null = the scene's choice.</param>
  /// <param name="progressive">Passes of samples or tiles (<see cref="DemoController.Progressive"/>); null = by the algorithm.</param>
  /// <param name="given">The settings the user changed, which win over the script's own values (<see cref="DemoController.Given"/>).</param>
  /// <returns>The render's number (<see cref="DemoController.RenderId"/>): the events of this render carry it.</returns>
  public long Render(SceneEntry entry, string param, RenderSettings settings, RenderAlgorithm? algorithm = null, bool? progressive = null,
                     GivenSettings given = GivenSettings.None)
  {
    Started();
    long id;
    Task<RenderResult?> rendering;
    // Requests arrive at once (two tabs, a script): each one's choices and number must stay its own.
    lock (starting)
    {
      entry.ParameterText = param;
      Controller.Selected = entry;
      Controller.Settings = settings;
      Controller.Given = given;
      Controller.Algorithm = algorithm;
      Controller.Progressive = progressive;
      (id, rendering) = Controller.StartRender();
    }
    _ = rendering.ContinueWith(t =>
    {
      lock (sync)
      {
        if (t.Exception != null && id == Controller.RenderId)   // not when a newer render replaced this one
        {
          error = t.Exception.GetBaseException().Message;
          errorSequence++;
        }
      }
      // Whatever ended it (done, failed, stopped, replaced), the phase may have changed.
      Changed();
    }, TaskScheduler.Default);
    return id;
  }

  /// <summary>
  /// Builds a saved script without rendering it (the watcher re-renders only the selected one), so its compiler
  /// diagnostics, or the error of running it, show in <see cref="Status"/> as a watched script's do. The phase is
  /// <c>compiling</c> meanwhile; <see cref="Stop"/> ends it.
  /// </summary>
  /// <returns>The check's number: <see cref="StudioStatus.CheckedId"/> becomes it when the check has ended.</returns>
  public long Check(SceneEntry entry)
  {
    long id;
    lock (sync)
    {
      id = ++checkId;
      checking = true;
      error = null;
      diagnostics = Array.Empty<ScriptError>();
      errorSequence++;
    }
    Changed();
    _ = CheckAsync(entry, id);
    return id;
  }

  async Task CheckAsync(SceneEntry entry, long id)
  {
    string? message = null;
    IReadOnlyList<ScriptError> found = [];
    try
    {
      await Controller.ReadScriptValuesAsync(entry).ConfigureAwait(false);
    }
    catch (Exception e) when (e is SceneEvaluationException or ArgumentException)
    {
      message = e.Message;
      found = ScriptErrors.In(DemoErrorEventArgs.DiagnosticsOf(e), entry.Path);
    }
    catch (OperationCanceledException)
    {
      // Stopped, or another scene's values asked for: nothing to report.
    }
    lock (sync)
    {
      if (id != checkId)
        return;
      checking = false;
      checkedId = id;
      if (message != null)
      {
        error = message;
        diagnostics = found;
        diagnosticsScene = entry.Name;
        errorSequence++;
      }
    }
    Changed();
  }

  /// <summary>Stops whatever runs: the script being built, the render, a saved script being compiled. Idle at once.</summary>
  public void Stop()
  {
    Controller.Stop();
    lock (sync)
    {
      stoppedAt ??= fraction;
      checkId++;
      checking = false;
    }
    Changed();
  }

  /// <summary>What the studio does now: <c>compiling</c> (a script being built: compiled and run), <c>rendering</c>,
  /// <c>stopping</c> (a render the user stopped, its workers still finishing) or <c>idle</c>.</summary>
  string Phase(bool building, bool busy) =>
    building || checking ? "compiling" : busy ? (stoppedAt != null ? "stopping" : "rendering") : "idle";

  // A render is starting (asked by the page, or a watched script changed): its state starts afresh.
  void Started()
  {
    Views = null;
    lock (sync)
    {
      error = null;
      diagnostics = Array.Empty<ScriptError>();
      stoppedAt = null;
      statistics = "";
      fraction = 0.0;
      elapsed = TimeSpan.Zero;
      samples = null;
      noise = null;
      errorSequence++;
    }
    Changed();
  }

  void Show(FloatImage shown, double g, double done)
  {
    lock (sync)
    {
      image = shown;
      gamma = g;
      fraction = stoppedAt ?? done;
      version++;
    }
    Changed();
  }

  /// <summary>What the page shows about the render now.</summary>
  public StudioStatus Status()
  {
    // The controller's state is read outside this session's lock, so its locks are never taken under ours and the two can't
    // wait for each other; read first, so a render that ends in between is seen ending in the next status (its end is a change).
    bool building = Controller.IsBuilding, busy = Controller.IsBusy;
    lock (sync)
      return new StudioStatus(busy, version, fraction, elapsed.TotalSeconds, statistics, error,
                              Controller.LastJob?.Notes ?? Array.Empty<string>(), diagnostics,
                              Controller.Algorithm is RenderAlgorithm a ? RenderAlgorithmNames.Name(a) : null)
      {
        DiagnosticsScene = diagnostics.Count > 0 ? diagnosticsScene : null,
        Phase = Phase(building, busy),
        Tab = Tab,
        Progressive = Controller.Progressive,
        Samples = samples,
        Noise = noise,
        RenderId = Controller.RenderId,
        Width = Controller.LastJob?.Width,
        Height = Controller.LastJob?.Height,
        SamplesPerPixel = Controller.LastJob?.Settings.SamplesPerPixel,
        ErrorSequence = errorSequence,
        Completions = completions,
        CompletedRenderId = completedId,
        Cancelled = cancelled,
        CheckedId = checkedId,
        Generation = Generation,
      };
  }

  /// <summary>
  /// A task that completes at the next change of the state (<see cref="Status"/>, the animation): ask for it before reading
  /// the state, so no change between the two is missed.
  /// </summary>
  public Task NextChange()
  {
    lock (sync)
      return changed.Task;
  }

  /// <summary>Tells whoever waits (<see cref="NextChange"/>) that the state changed.</summary>
  internal void Changed()
  {
    TaskCompletionSource done;
    lock (sync)
    {
      done = changed;
      changed = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
    }
    done.TrySetResult();
  }

  /// <summary>The event streams open now (<see cref="StudioEvents"/>): each ends when its page goes or the studio stops.</summary>
  public int EventStreams => Volatile.Read(ref streams);

  internal void StreamOpened() => Interlocked.Increment(ref streams);

  internal void StreamClosed() => Interlocked.Decrement(ref streams);

  /// <summary>The image now on show as the 8-bit display image (gamma applied, quantised as <c>grcis render</c> saves it).</summary>
  public (Rgb8Image Image, int Version)? DisplayImage()
  {
    lock (sync)
      return image == null ? null : (Rendering.Execution.RenderSetup.ToDisplayImage(image, gamma), version);
  }

  (RenderJob Job, IReadOnlyList<(OpenTK.Mathematics.Vector3d Min, OpenTK.Mathematics.Vector3d Max)> Boxes)? boxes;

  /// <summary>
  /// World boxes of the last render's scene members (<see cref="Rendering.Accel.PreparedScene.WorldBoxes"/>), or null before a
  /// render. The render's own prepared snapshot is read when its ray tracer kept one of this scene; otherwise (the faithful
  /// path, another image function, per-worker clones) the snapshot is built once per render and kept.
  /// </summary>
  public IReadOnlyList<(OpenTK.Mathematics.Vector3d Min, OpenTK.Mathematics.Vector3d Max)>? SceneBoxes()
  {
    RenderJob? job = Controller.LastJob;
    if (job is null)
      return null;
    lock (sync)
      if (boxes is { } kept && ReferenceEquals(kept.Job, job))
        return kept.Boxes;
    Rendering.Accel.PreparedScene prepared =
      job.ImageFunction is Rendering.RayCasting { LastPrepared: { } used } && ReferenceEquals(used.Source, job.Scene.Intersectable)
        ? used
        : Rendering.Accel.PreparedScene.Prepare(job.Scene.Intersectable);
    var found = prepared.WorldBoxes();
    lock (sync)
      boxes = (job, found);
    return found;
  }

  /// <summary>The last still render's scene as triangles and its parts, made once per render (the 3D view, the probe, the hit points).</summary>
  internal StillScene StillScene { get; } = new();

  /// <summary>The final linear image of the last finished render, or null.</summary>
  public FloatImage? FinalImage() => Controller.LastResult?.Image;

  /// <summary>The extra views of the last render, once computed (<see cref="ComputeViews"/>); a new render drops them.</summary>
  public ExtraViews? Views { get; private set; }

  /// <summary>Computes the depth, normal and ray maps of the last render.</summary>
  /// <exception cref="InvalidOperationException">Nothing rendered yet, or a render is running.</exception>
  public ExtraViews ComputeViews(System.Threading.CancellationToken cancel) => Views = Controller.ComputeExtraViews(cancel);

  /// <summary>The page (browser tab) that asked for the work on show: one studio serves one render, so a tab whose own is
  /// replaced by another's says so (<see cref="StudioStatus.Tab"/>). Null = none named (a script saved by another editor).</summary>
  public string? Tab { get; private set; }

  /// <summary>The header in which a page names itself (a random id per page load).</summary>
  public const string TabHeader = "X-GrCis-Tab";

  /// <summary>Records the tab of a request that starts work, from its <see cref="TabHeader"/> (ignored when absent or too long).</summary>
  public void ActedFor(Microsoft.AspNetCore.Http.HttpRequest request)
  {
    string? tab = request.Headers[TabHeader];
    Tab = string.IsNullOrEmpty(tab) || tab.Length > 64 ? null : tab;
    Changed();
  }

  /// <summary>The last animation run, if any; it announces its frames and its end as changes of the session.</summary>
  public StudioAnimation? Animation
  {
    get => animation;
    set
    {
      animation = value;
      Changed();
    }
  }

  StudioAnimation? animation;

  /// <summary>Shows a render of the history (back/forward).</summary>
  public void ShowRecord(RenderRecord record) => Show(record.Image, record.Gamma, 1.0);

  /// <summary>The script host the session's catalog compiles with, disposed with the session (null = the caller's).</summary>
  public GrCis.Scripting.ScriptHost? Scripts { get; init; }

  public void Dispose()
  {
    Controller.Dispose();
    Scripts?.Dispose();
  }
}
