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
}
