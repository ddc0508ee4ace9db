using System;
using System.Diagnostics;
using System.IO;
using System.Threading;
using System.Threading.Tasks;
using GrCis.Hosting;
using GrCis.TestSupport;

namespace GrCis.Interactive.Tests;

/// <summary>
/// <see cref="DemoController.SettleAsync"/>: what the studio asks before an action that needs the render to be over (an
/// animation, a move in the history, the extra views). A render the status shows as idle may still be ending: after Stop,
/// a script's class that ignores the stop (a sleep, not a loop) finishes its call, and only then does the stopped render
/// complete and add its image to the history.
/// </summary>
public class SettleTests
{
  /// <summary>A render of <see cref="StuckScripts.Sleeping"/> whose texture has started its sleep.</summary>
  sealed class SleepingRender : IDisposable
  {
    readonly TempDir tmp = new();
    readonly GrCis.Scripting.ScriptHost evaluator = new();

    public DemoController Demo { get; }

    public Task<RenderResult?> Render { get; }

    public SleepingRender(int sleep, TimeSpan abandonAfter)
    {
      string marker = tmp.File("started").Replace("\\", "/", StringComparison.Ordinal);
      File.WriteAllText(tmp.File("Sleepy.cs"), StuckScripts.Sleeping(marker, sleep));
      var catalog = new SceneCatalog(evaluator);
      SceneEntry entry = catalog.AddScriptFile(tmp.File("Sleepy.cs"));
      Demo = new DemoController(catalog)
      {
        Selected = entry,
        Settings = new RenderSettings { SamplesPerPixel = 1, Threads = 1 },
        AbandonStuckScriptAfter = abandonAfter,
      };
      Render = Demo.RenderAsync();
      var clock = Stopwatch.StartNew();
      while (!File.Exists(marker))
      {
        Assert.True(clock.Elapsed < TimeSpan.FromSeconds(60), "the render never reached the script's texture");
        Thread.Sleep(20);
      }
    }

    public void Dispose()
    {
      Demo.Stop();
      Render.Wait(TimeSpan.FromSeconds(30));
      Demo.Dispose();
      evaluator.Dispose();
      tmp.Dispose();
    }
  }

  [Fact]
  public async Task A_busy_render_is_refused_at_once()
  {
    using var sleeping = new SleepingRender(3000, TimeSpan.FromSeconds(2));
    Assert.False(await sleeping.Demo.SettleAsync());
    // It did not wait for the render: the texture is still asleep.
    Assert.True(sleeping.Demo.IsBusy);
    Assert.False(sleeping.Render.IsCompleted);
  }

  [Fact]
  public async Task A_stopped_render_that_is_still_ending_is_waited_for_and_has_added_its_image_when_settled()
  {
    using var sleeping = new SleepingRender(1500, TimeSpan.FromSeconds(30));
    DemoController demo = sleeping.Demo;
    int kept = demo.History.Items.Count;

    demo.Stop();
    // What the status shows (idle), and what is true (the texture's call still runs).
    Assert.False(demo.IsBusy);
    Assert.True(demo.IsRendering);

    Assert.True(await demo.SettleAsync());
    Assert.False(demo.IsRendering);
    Assert.True(sleeping.Render.IsCompleted);
    RenderResult stopped = (await sleeping.Render)!;
    Assert.True(stopped.Cancelled);
    // The stopped render's image came in before the wait ended, so an action after it (a move back) sees it in place.
    Assert.Equal(kept + 1, demo.History.Items.Count);
    Assert.Same(demo.History.Current, demo.History.Items[^1]);
  }

  [Fact]
  public async Task A_stopped_render_still_ending_after_the_allowed_wait_is_refused_then_settles()
  {
    using var sleeping = new SleepingRender(2500, TimeSpan.FromMilliseconds(100));
    DemoController demo = sleeping.Demo;
    demo.Stop();
    Assert.False(await demo.SettleAsync());
    Assert.False(demo.IsBusy);
    Assert.True(demo.IsRendering);

    await sleeping.Render.WaitAsync(TimeSpan.FromSeconds(30));
    Assert.True(await demo.SettleAsync());
  }

  [Fact]
  public async Task Nothing_rendered_yet_or_a_finished_render_settles_at_once()
  {
    using var tmp = new TempDir();
    using var evaluator = new GrCis.Scripting.ScriptHost();
    File.WriteAllText(tmp.File("Plain.cs"), TestScripts.Background(0.25, 4, 3));
    var catalog = new SceneCatalog(evaluator);
    using var demo = new DemoController(catalog) { Selected = catalog.AddScriptFile(tmp.File("Plain.cs")) };
    Assert.True(await demo.SettleAsync());
    Assert.True((await demo.RenderAsync())!.Succeeded);
    Assert.True(await demo.SettleAsync());
    Assert.False(demo.IsRendering);
  }
}
