using System;
using System.Collections.Generic;
using System.Net.ServerSentEvents;
using System.Runtime.CompilerServices;
using System.Threading;
using System.Threading.Tasks;

namespace GrCis.Studio;

/// <summary>
/// The studio's state pushed to a page as Server-Sent Events (<c>GET /api/events</c>): a <c>status</c> snapshot first (the
/// whole of <c>/api/status</c>, so a page that connects or reconnects is never stale), then one event per change, each
/// carrying the number of the render it belongs to, so a page ignores those of a render it has seen replaced. A change
/// goes out at once; what changes within <see cref="Coalesce"/> after it (tiles, previews) goes out together in the next
/// batch. What a batch says is read from the state then, so nothing is lost and a late event never contradicts an earlier state.
/// </summary>
internal static class StudioEvents
{
  /// <summary>The shortest time between two batches of events: at most 20 a second, whatever the render's pace.</summary>
  public static readonly TimeSpan Coalesce = TimeSpan.FromMilliseconds(50);

  /// <summary>A <c>ping</c> after this long without news, so a page gone without a word is noticed by the failed write.</summary>
  public static readonly TimeSpan KeepAlive = TimeSpan.FromSeconds(15);

  /// <summary>How long a page's EventSource waits before it reconnects (sent with the first event).</summary>
  public static readonly TimeSpan Retry = TimeSpan.FromSeconds(1);

  /// <summary>A new render (Render, a saved script re-rendered) or another tab's request: the page starts this render's state afresh.</summary>
  internal sealed record RenderEvent(long RenderId, string? Tab);

  /// <summary><c>compiling</c>, <c>rendering</c> or <c>idle</c>; the notes are the render's job's (its script's choices).</summary>
  internal sealed record PhaseEvent(long RenderId, string Phase, bool Rendering, IReadOnlyList<string> Notes);

  internal sealed record ProgressEvent(long RenderId, double Fraction, double Seconds, int? Samples, double? Noise);

  /// <summary>A new image at <c>/api/image.png</c> (a preview, the final image, a render of the history).</summary>
  internal sealed record PreviewEvent(long RenderId, int Version);

  /// <summary>The error and the compiler diagnostics, set or cleared (null and none: the script compiled).</summary>
  internal sealed record ErrorsEvent(long RenderId, string? Error, IReadOnlyList<ScriptError> Diagnostics, string? Scene);

  /// <summary>A saved script's check (<c>PUT /api/source</c>'s <c>check</c>) ended; its errors, if any, came before.</summary>
  internal sealed record CheckedEvent(long RenderId, long Check, bool Compiles);

  /// <summary>The render finished (or was stopped: <c>cancelled</c>); its statistics and what it used.</summary>
  internal sealed record DoneEvent(long RenderId, bool Cancelled, string Statistics, int? Samples, double? Noise, int? Width, int? Height,
                                   int? SamplesPerPixel, int Version);

  /// <summary>
  /// The events of one page until it goes (<paramref name="aborted"/>) or the studio stops (<paramref name="stopping"/>): both end
  /// the stream, so no stream outlives its page and none holds up the studio's shutdown.
  /// </summary>
  public static async IAsyncEnumerable<SseItem<object>> Stream(StudioSession session, CancellationToken stopping,
                                                                [EnumeratorCancellation] CancellationToken aborted = default)
  {
    using var ended = CancellationTokenSource.CreateLinkedTokenSource(stopping, aborted);
    session.StreamOpened();
    try
    {
      // Asked for before the state is read: a change in between completes it, so none is missed.
      Task next = session.NextChange();
      StudioStatus last = session.Status();
      AnimationStatus? lastAnimation = session.Animation?.Status();
      yield return new SseItem<object>(last, "status") { ReconnectionInterval = Retry };
      if (lastAnimation != null)
        yield return new SseItem<object>(lastAnimation, "animation");
      while (true)
      {
        bool news = await Wait(next, KeepAlive, ended.Token).ConfigureAwait(false);
        if (ended.IsCancellationRequested)
          yield break;
        if (!news)
        {
          yield return new SseItem<object>(last.RenderId, "ping");
          continue;
        }
        next = session.NextChange();
        StudioStatus now = session.Status();
        foreach ((string name, object data) in Changes(last, now))
          yield return new SseItem<object>(data, name);
        last = now;
        AnimationStatus? animation = session.Animation?.Status();
        if (animation != null && animation != lastAnimation)
          yield return new SseItem<object>(animation, "animation");
        lastAnimation = animation;
        // The pace: what changes meanwhile goes out together in the next batch.
        await Wait(Task.Delay(Coalesce, ended.Token), Timeout.InfiniteTimeSpan, ended.Token).ConfigureAwait(false);
        if (ended.IsCancellationRequested)
          yield break;
      }
    }
    finally
    {
      session.StreamClosed();
    }
  }

  /// <summary>
  /// The events that take a page from <paramref name="before"/> to <paramref name="now"/>, in the order it applies them:
  /// the new render first (it clears the old one's state), its errors before its phase (a page that sees the phase go idle
  /// knows by then whether the script compiled), the phase last.
  /// </summary>
  internal static IEnumerable<(string Name, object Data)> Changes(StudioStatus before, StudioStatus now)
  {
    long id = now.RenderId;
    bool fresh = id != before.RenderId;
    if (fresh || now.Tab != before.Tab)
      yield return ("render", new RenderEvent(id, now.Tab));
    if (now.ErrorSequence != before.ErrorSequence)
      yield return ("errors", new ErrorsEvent(id, now.Error, now.Diagnostics, now.DiagnosticsScene));
    if (fresh || now.Fraction != before.Fraction || now.Seconds != before.Seconds || now.Samples != before.Samples || now.Noise != before.Noise)
      yield return ("progress", new ProgressEvent(id, now.Fraction, now.Seconds, now.Samples, now.Noise));
    if (now.Version != before.Version)
      yield return ("preview", new PreviewEvent(id, now.Version));
    // A completion raised for a render since replaced is not this render's.
    if (now.Completions != before.Completions && now.CompletedRenderId == id)
      yield return ("done", new DoneEvent(id, now.Cancelled, now.Statistics, now.Samples, now.Noise, now.Width, now.Height, now.SamplesPerPixel, now.Version));
    if (now.CheckedId != before.CheckedId)
      yield return ("checked", new CheckedEvent(id, now.CheckedId, now.Error == null && now.Diagnostics.Count == 0));
    if (fresh || now.Phase != before.Phase || now.Rendering != before.Rendering || !ReferenceEquals(now.Notes, before.Notes))
      yield return ("phase", new PhaseEvent(id, now.Phase, now.Rendering, now.Notes));
  }

  /// <summary>Waits for <paramref name="task"/> at most <paramref name="timeout"/>: true when it completed; false on time-out or when <paramref name="cancel"/> ends it.</summary>
  static async Task<bool> Wait(Task task, TimeSpan timeout, CancellationToken cancel)
  {
    try
    {
      await task.WaitAsync(timeout, cancel).ConfigureAwait(false);
      return true;
    }
    catch (Exception e) when (e is TimeoutException or OperationCanceledException)
    {
      return false;
    }
  }
}
