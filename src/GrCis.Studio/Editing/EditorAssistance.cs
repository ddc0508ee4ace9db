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
/// (<see cref="ScriptAssistant"/>, made on the first request: it loads the references' metadata, a few seconds)
/// and checks of unsaved text by the compiler the render uses, so the marks match what a save would report.
/// </summary>
public sealed class EditorAssistance(StudioSession session) : IDisposable
{
  readonly Lazy<ScriptAssistant> assistant = new(() => new ScriptAssistant(session.Scripts?.Modules), LazyThreadSafetyMode.ExecutionAndPublication);

  // One check at a time: each is a whole compilation, and the page waits for its latest anyway.
  readonly SemaphoreSlim checking = new(1, 1);

  public ScriptAssistant Assistant => assistant.Value;

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
    if (assistant.IsValueCreated)
      assistant.Value.Dispose();
    checking.Dispose();
  }
}
