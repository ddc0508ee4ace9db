using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Threading;
using System.Threading.Tasks;
using GrCis.Hosting;
using GrCis.TestSupport;

namespace GrCis.Interactive.Tests;

/// <summary>
/// The controller's state can be trusted: a render replaced by a second Render says nothing more (only the second one's
/// previews and completion arrive), busy covers the build and the render of the render asked for last, Stop ends it at
/// once, and a size that does not fit in memory is refused before any work, as <c>grcis render</c> refuses it.
/// </summary>
public class RenderStateTests
{
  [Fact]
  public async Task Each_render_asked_for_is_announced_with_its_number_while_busy_building()
  {
    using DemoController demo = FiveBalls(new RenderSettings { Width = 16, Height = 12, Threads = 2 });
    var started = new List<(long Id, bool Building)>();
    demo.RenderStarted += (_, id) => started.Add((id, demo.IsBuilding));
    await demo.RenderAsync();
    await demo.RenderAsync();
    Assert.Equal([(1L, true), (2L, true)], started);
  }

  [Fact]
  public async Task The_state_can_be_read_from_another_thread_while_the_built_scene_is_announced()
  {
    using DemoController demo = FiveBalls(new RenderSettings { Width = 16, Height = 12, Threads = 2 });
    bool? answered = null;
    demo.SceneEvaluated += (_, _) =>
    {
      // A front end's status reader (the studio's event stream) reads the state at any moment; here while the event is
      // raised. Raised under the controller's lock, the read would wait for this handler, which waits for the read.
      Task<(bool, bool)> read = Task.Run(() => (demo.IsBuilding, demo.IsBusy));
      answered = read.Wait(TimeSpan.FromSeconds(30));
    };
    RenderResult? result = await demo.RenderAsync();
    Assert.NotNull(result);
    Assert.True(answered, "the controller's state could not be read from another thread while SceneEvaluated was being raised");
  }

  [Fact]
  public async Task A_second_render_replaces_the_first_and_only_its_events_arrive()
  {
    // Big enough to be still running when the second render is asked for.
    using DemoController demo = FiveBalls(new RenderSettings { Width = 1600, Height = 1200, SamplesPerPixel = 16, Threads = 2 });
    demo.PreviewInterval = TimeSpan.FromMilliseconds(50);
    var completed = new List<RenderResult>();
    var previewed = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
    int secondPreviews = 0;
    demo.RenderCompleted += (_, e) => { lock (completed) completed.Add(e.Result); };
    demo.PreviewReady += (_, e) =>
    {
      if (e.Image.Width == 32)
        Interlocked.Increment(ref secondPreviews);
      else
        previewed.TrySetResult();
    };

    Task<RenderResult?> first = demo.RenderAsync();
    await previewed.Task.WaitAsync(TimeSpan.FromMinutes(1));
    Assert.True(demo.IsBusy);
    demo.Settings = new RenderSettings { Width = 32, Height = 24, Threads = 2 };
    Task<RenderResult?> second = demo.RenderAsync();
    Assert.Equal(2, demo.RenderId);
    // (Not asserted busy here: a 32x24 render may finish before the next line; Busy_covers_the_build_and_stop_ends_it_at_once covers the state.)

    RenderResult? replaced = await first.WaitAsync(TimeSpan.FromMinutes(1));
    Assert.True(replaced == null || replaced.Cancelled);
    RenderResult done = (await second.WaitAsync(TimeSpan.FromMinutes(1)))!;
    Assert.True(done.Succeeded);
    Assert.False(demo.IsBusy);
    lock (completed)
      Assert.Equal(32, Assert.Single(completed).Image.Width);
    Assert.Same(done, demo.LastResult);
    Assert.Single(demo.History.Items);
    Assert.True(secondPreviews > 0);
  }

  [Fact]
  public async Task Busy_covers_the_build_and_stop_ends_it_at_once()
  {
    using var tmp = new TempDir();
    string marker = tmp.File("started").Replace("\\", "/", StringComparison.Ordinal);
    File.WriteAllText(tmp.File("Stuck.cs"), StuckScripts.WhileBuilding(marker));
    using var scripts = new GrCis.Scripting.ScriptHost();
    var catalog = new SceneCatalog(scripts);
    using var demo = new DemoController(catalog) { Selected = catalog.AddScriptFile(tmp.File("Stuck.cs")) };

    Task<RenderResult?> stuck = demo.RenderAsync();
    var clock = Stopwatch.StartNew();
    while (!File.Exists(marker))
    {
      Assert.True(clock.Elapsed < TimeSpan.FromMinutes(1), "the script never started");
      await Task.Delay(20);
    }
    Assert.True(demo.IsBusy, "busy while the script builds its scene");
    Assert.False(demo.IsRendering);
    demo.Stop();
    Assert.False(demo.IsBusy, "still busy after Stop");
    Assert.Null(await stuck.WaitAsync(TimeSpan.FromSeconds(30)));
    Assert.False(demo.IsBusy);
  }

  [Fact]
  public async Task A_size_that_does_not_fit_in_memory_is_refused_before_any_work()
  {
    using DemoController demo = FiveBalls(new RenderSettings { Width = 16384, Height = 16384 });
    demo.MemoryLimit = 1L << 30;
    string? error = null;
    demo.Error += (_, e) => error = e.Message;

    Assert.Null(await demo.RenderAsync());
    Assert.StartsWith("a 16384x16384 image needs about 20.1 GiB of memory, but this process can use 1.0 GiB", error);
    Assert.False(demo.IsBusy);
    Assert.Empty(demo.History.Items);
    var e = Assert.Throws<InvalidSettingException>(() => demo.CreateAnimation(0, 1, 1));
    Assert.Equal(Setting.Size, e.Setting);

    // What fits renders.
    demo.Settings = new RenderSettings { Width = 64, Height = 48 };
    Assert.True((await demo.RenderAsync())!.Succeeded);
  }

  /// <summary>A controller over the built-in scenes with Five balls selected and <paramref name="settings"/>.</summary>
  static DemoController FiveBalls(RenderSettings settings)
  {
    var catalog = SceneCatalog.WithBuiltInScenes();
    return new DemoController(catalog) { Settings = settings, Selected = catalog.Find("Five balls") };
  }
}
