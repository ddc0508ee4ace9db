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
  static DemoController Demo(TempDir tmp, GrCis.Scripting.ScriptHost evaluator, string marker, int sleep)
  {
    File.WriteAllText(tmp.File("Sleepy.cs"), StuckScripts.Sleeping(marker, sleep));
    var catalog = new SceneCatalog(evaluator);
    SceneEntry entry = catalog.AddScriptFile(tmp.File("Sleepy.cs"));
    return new DemoController(catalog) { Selected = entry, Settings = new RenderSettings { SamplesPerPixel = 1, Threads = 1 } };
  }

  static void WaitForFile(string path)
  {
    var clock = Stopwatch.StartNew();
    while (!File.Exists(path))
    {
      Assert.True(clock.Elapsed < TimeSpan.FromSeconds(60), "the render never reached the script's texture");
      Thread.Sleep(20);
    }
  }

  [Fact]
  public async Task A_busy_render_is_refused_at_once()
  {
    using var tmp = new TempDir();
    string marker = tmp.File("started").Replace("\\", "/", StringComparison.Ordinal);
    using var evaluator = new GrCis.Scripting.ScriptHost();
    using DemoController demo = Demo(tmp, evaluator, marker, 3000);
    Task<RenderResult?> render = demo.RenderAsync();
    WaitForFile(marker);

    Assert.False(await demo.SettleAsync());
    // It did not wait for the render: the texture is still asleep.
    Assert.True(demo.IsBusy);
    Assert.False(render.IsCompleted);
    demo.Stop();
    await render.WaitAsync(TimeSpan.FromSeconds(30));
  }

  [Fact]
  public async Task A_stopped_render_that_is_still_ending_is_waited_for_and_has_added_its_image_when_settled()
  {
    using var tmp = new TempDir();
    string marker = tmp.File("started").Replace("\\", "/", StringComparison.Ordinal);
    using var evaluator = new GrCis.Scripting.ScriptHost();
    using DemoController demo = Demo(tmp, evaluator, marker, 1500);
    demo.AbandonStuckScriptAfter = TimeSpan.FromSeconds(30);
    Task<RenderResult?> render = demo.RenderAsync();
    WaitForFile(marker);
    int kept = demo.History.Items.Count;

    demo.Stop();
    // What the status shows (idle), and what is true (the texture's call still runs).
    Assert.False(demo.IsBusy);
    Assert.True(demo.IsRendering);

    Assert.True(await demo.SettleAsync());
    Assert.False(demo.IsRendering);
    Assert.True(render.IsCompleted);
    RenderResult stopped = (await render)!;
    Assert.True(stopped.Cancelled);
    // The stopped render's image came in before the wait ended, so an action after it (a move back) sees it in place.
    Assert.Equal(kept + 1, demo.History.Items.Count);
    Assert.Same(demo.History.Current, demo.History.Items[^1]);
  }

  [Fact]
  public async Task A_stopped_render_still_ending_after_the_allowed_wait_is_refused_then_settles()
  {
    using var tmp = new TempDir();
    string marker = tmp.File("started").Replace("\\", "/", StringComparison.Ordinal);
    using var evaluator = new GrCis.Scripting.ScriptHost();
    using DemoController demo = Demo(tmp, evaluator, marker, 2500);
    demo.AbandonStuckScriptAfter = TimeSpan.FromMilliseconds(100);
    Task<RenderResult?> render = demo.RenderAsync();
    WaitForFile(marker);

    demo.Stop();
    Assert.False(await demo.SettleAsync());
    Assert.False(demo.IsBusy);
    Assert.True(demo.IsRendering);

    await render.WaitAsync(TimeSpan.FromSeconds(30));
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
