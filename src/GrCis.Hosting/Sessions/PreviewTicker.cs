using System;
using System.Threading;

namespace GrCis.Hosting;

/// <summary>
/// Calls an action at a fixed interval on a thread of its own until disposed: previews keep coming while the
/// render's workers (and anything else on the machine) keep the thread pool busy.
/// </summary>
internal sealed class PreviewTicker : IDisposable
{
  readonly ManualResetEventSlim stop = new();
  readonly Thread thread;

  public PreviewTicker(TimeSpan interval, Action tick)
  {
    thread = new Thread(() =>
    {
      while (!stop.Wait(interval))
        tick();
    })
    { IsBackground = true, Name = "grcis-preview" };
    thread.Start();
  }

  /// <summary>Stops the ticks; returns after the last one has finished.</summary>
  public void Dispose()
  {
    stop.Set();
    if (Thread.CurrentThread != thread)
      thread.Join();
    stop.Dispose();
  }
}
