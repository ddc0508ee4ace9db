using System;
using System.Threading;
using System.Threading.Tasks;
using GrCis.Hosting;
using GrCis.Interactive;

namespace GrCis.Studio.Tests;

/// <summary>
/// Each page's event stream reads the status at every change, on threads of its own, while the controller raises the
/// render's events: the two never wait for each other. (A status read holding the session's lock, waiting for the
/// controller's, while the controller, holding its own, announced the built scene and waited for the session's, once froze
/// a studio for good: that render and every later one never ended.)
/// </summary>
public sealed class StatusReadingTests
{
  const int Renders = 40;

  [Fact]
  public async Task Renders_run_to_the_end_or_replaced_all_finish_while_the_status_is_read_without_pause()
  {
    var catalog = SceneCatalog.WithBuiltInScenes();
    var session = new StudioSession(new DemoController(catalog));
    SceneEntry entry = catalog.Find("Five balls")!;
    // Path tracing in passes, as the browser tests' renders that froze.
    var settings = new RenderSettings { Width = 32, Height = 24, SamplesPerPixel = 16, Threads = 2 };
    using var stop = new CancellationTokenSource();
    long reads = 0;
    var readers = new Thread[2];
    for (int r = 0; r < readers.Length; r++)
    {
      readers[r] = new Thread(() =>
      {
        while (!stop.IsCancellationRequested)
        {
          session.Status();
          Interlocked.Increment(ref reads);
        }
      })
      { IsBackground = true, Name = $"status-reader-{r}" };
      readers[r].Start();
    }

    int finished = 0;
    // On a thread of its own: a deadlock fails the test after a while instead of hanging the run (its threads are left behind).
    Task renders = Task.Factory.StartNew(() =>
    {
      for (int i = 0; i < Renders; i++)
      {
        long id = session.Render(entry, "", settings, RenderAlgorithm.Path);
        if (i % 4 == 1)
          continue;                 // replaced at once by the next
        if (i % 4 == 2)
        {
          Thread.Sleep(5);          // replaced while it builds or renders
          continue;
        }
        StudioStatus s;
        while ((s = session.Status()).CompletedRenderId != id || s.Phase != "idle")
          Thread.Sleep(1);
        Interlocked.Increment(ref finished);
      }
    }, TaskCreationOptions.LongRunning);

    bool ended = await Task.WhenAny(renders, Task.Delay(TimeSpan.FromMinutes(2))) == renders;
    Assert.True(ended, $"stuck after {Volatile.Read(ref finished)} finished renders, {Interlocked.Read(ref reads)} status reads; " +
                       StudioState.Describe(session));
    await renders;
    stop.Cancel();
    foreach (Thread reader in readers)
      reader.Join();
    Assert.True(Interlocked.Read(ref reads) > Renders, "the status was read while the renders ran");
    session.Dispose();
  }
}
