using System.Threading.Tasks;
using GrCis.Hosting;

namespace GrCis.Interactive;

public sealed partial class DemoController
{
  // What the last Stop stopped (set there), which a script that ignores the stop keeps running.
  Task? stoppedBuild;
  RenderSession? stoppedSession;

  /// <summary>
  /// True while what the last <see cref="Stop"/> stopped (the script being built, the render) still runs: a script that
  /// ignores the stop (a loop in code the script host does not instrument) keeps it true, however many renders start
  /// after it. A supervisor (the studio's) ends the process when it stays true after a grace time.
  /// </summary>
  public bool StoppedWorkRunning
  {
    get
    {
      lock (sync)
        return stoppedBuild is { IsCompleted: false } || stoppedSession?.IsRunning == true;
    }
  }

  /// <summary>
  /// Waits until no render session runs, when none is <see cref="IsBusy"/>: a render that has finished, or was stopped, may
  /// still be ending (its completion being handled, the tiles in progress of a stopped one, a script that ignores the
  /// stop). Gives it up to <see cref="AbandonStuckScriptAfter"/>, as a new render gives a stopped script. True when no
  /// session runs any more; false at once while the render is busy, or when the session is still running after the wait.
  /// </summary>
  public async Task<bool> SettleAsync()
  {
    Task? running;
    lock (sync)
    {
      if (BusyLocked)
        return false;
      running = session is { IsRunning: true } s ? s.Task : null;
    }
    if (running != null)
      await Task.WhenAny(running, Task.Delay(AbandonStuckScriptAfter)).ConfigureAwait(false);
    return !IsRendering;
  }
}
