using System;
using System.IO;
using System.Runtime.InteropServices;
using System.Threading;

namespace GrCis.Cli;

/// <summary>
/// Ctrl+C (SIGINT) for the real process: the first one cancels cooperatively, so a render stops
/// between tiles and says what was not written; if the work has not ended after <see cref="Grace"/>
/// (a scene script stuck in a loop never looks at the token, nor does a tile with huge spp), the
/// process exits with 130 anyway. Nothing is half-written either way: images are saved through a
/// temporary file that <see cref="Rendering.Imaging.AtomicFile"/> removes on exit.
/// <para>
/// The signals are taken with <see cref="PosixSignalRegistration"/> (SIGINT for Ctrl+C, SIGQUIT for Ctrl+\ or Ctrl+Break,
/// the two <see cref="Console.CancelKeyPress"/> reports, on Windows too): subscribing to that event sets up the terminal
/// first, which cost every run about 10 ms of its start.
/// </para>
/// </summary>
internal sealed class InterruptGuard : IDisposable
{
  /// <summary>How long cooperative cancellation may take before the process is ended.</summary>
  public static readonly TimeSpan Grace = TimeSpan.FromSeconds(2);

  readonly CancellationTokenSource cts = new();
  readonly TextWriter error;
  readonly PosixSignalRegistration interrupt, quit;
  Timer? deadline;

  public InterruptGuard(TextWriter error)
  {
    this.error = error;
    interrupt = PosixSignalRegistration.Create(PosixSignal.SIGINT, OnSignal);
    quit = PosixSignalRegistration.Create(PosixSignal.SIGQUIT, OnSignal);
  }

  public CancellationToken Token => cts.Token;

  void OnSignal(PosixSignalContext context)
  {
    context.Cancel = true;
    if (cts.IsCancellationRequested)
    {
      Stop("interrupted twice");   // a second Ctrl+C: no more waiting
      return;
    }
    cts.Cancel();
    deadline = new Timer(_ => Stop($"interrupted; the scene did not stop within {Grace.TotalSeconds:0} s"), null, Grace, Timeout.InfiniteTimeSpan);
  }

  void Stop(string why)
  {
    try
    {
      error.WriteLine($"grcis: error: {why}; no file was left half-written");
      error.Flush();
    }
    finally
    {
      Environment.Exit(ExitCodes.Cancelled);
    }
  }

  public void Dispose()
  {
    interrupt.Dispose();
    quit.Dispose();
    deadline?.Dispose();
    cts.Dispose();
  }
}
