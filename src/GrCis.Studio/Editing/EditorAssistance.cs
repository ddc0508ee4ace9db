using System;
using System.Collections.Generic;
using System.Linq;
using System.Threading;
using System.Threading.Tasks;
using GrCis.Editing;
using GrCis.Scripting;

namespace GrCis.Studio;

/// <summary>
/// The editor's language services for one studio: Roslyn's completion, signature help and hover
/// (<see cref="ScriptAssistant"/>, made in the background when the studio starts: it loads the references' metadata,
/// a few seconds)
/// and checks of unsaved text by the compiler the render uses, so the marks match what a save would report.
/// </summary>
public sealed class EditorAssistance(StudioSession session) : IDisposable
{
  readonly Lazy<ScriptAssistant> assistant = new(() => new ScriptAssistant(session.Scripts?.Modules), LazyThreadSafetyMode.ExecutionAndPublication);

  // One check at a time: each is a whole compilation, and the page waits for its latest anyway.
  readonly SemaphoreSlim checking = new(1, 1);

  public ScriptAssistant Assistant => assistant.Value;

  // A short script whose completion walks the paths a page's first request takes (symbols, member lists, docs).
  const string WarmText = "var m = new PhongMaterial(new double[] { 1.0, 0.5, 0.2 }, 0.1, 0.8, 0.2, 16);\nscene.";

  // Ends the warm-up when the studio stops (Dispose).
  readonly CancellationTokenSource stopped = new();

  /// <summary>
  /// Loads the language services and runs one completion in the background, so that the page's first completion
  /// finds them ready instead of paying their few seconds of loading (started before the studio's server starts, or by
  /// the first <see cref="ReadyAsync"/>); started once, later calls return the same warm-up.
  /// </summary>
  internal Task WarmAsync()
  {
    lock (warming)
      return Warmed ??= Task.Run(async () =>
      {
        try
        {
          await Assistant.CompleteAsync(WarmText, WarmText.Length, cancel: stopped.Token).ConfigureAwait(false);
        }
        catch (Exception e) when (e is OperationCanceledException or ObjectDisposedException)
        {
          // The studio stopped first.
        }
      }, CancellationToken.None);
  }

  readonly object warming = new();

  /// <summary>The warm-up started with the studio, or null before it starts.</summary>
  internal Task? Warmed { get; private set; }

  /// <summary>
  /// Completes when the language services answer at their warm speed (starting the warm-up if the studio did not),
  /// or when the studio stops: the page shows that they are loading until then. <paramref name="cancel"/> ends only the wait.
  /// </summary>
  public Task ReadyAsync(CancellationToken cancel) => WarmAsync().WaitAsync(cancel);

  /// <summary>True once the language services are loaded.</summary>
  internal bool Loaded => assistant.IsValueCreated;

  /// <summary>The compiler's errors and warnings for <paramref name="text"/> as the script <paramref name="path"/>, without saving it.</summary>
  public async Task<IReadOnlyList<ScriptError>> CheckAsync(string text, string path, CancellationToken cancel)
  {
    ScriptHost scripts = session.Scripts ?? throw new InvalidOperationException("this studio runs no scripts");
    await checking.WaitAsync(cancel).ConfigureAwait(false);
    try
    {
      IReadOnlyList<ScriptDiagnostic> found = await Task.Run(() => scripts.Check(text, path), cancel).ConfigureAwait(false);
      return ScriptErrors.In(found, path);
    }
    finally
    {
      checking.Release();
    }
  }

  public void Dispose()
  {
    lock (warming)
      stopped.Cancel();
    if (assistant.IsValueCreated)
      assistant.Value.Dispose();
    checking.Dispose();
  }
}
