using System;
using GrCis.TestSupport;
using System.Diagnostics;
using System.IO;
using System.Threading;
using System.Threading.Tasks;

using GrCis.Hosting;

namespace GrCis.Interactive.Tests;

/// <summary>
/// A student's script stuck in an endless loop, while it builds the scene or while the render calls one
/// of its classes, never blocks the demo's caller (the UI thread), Stop ends it, and the demo goes on.
/// </summary>
public class StuckScriptTests
{
  static (DemoController Demo, GrCis.Scripting.ScriptHost Evaluator, SceneEntry Stuck, SceneEntry Good) Demo(TempDir tmp, string stuckScript)
  {
    File.WriteAllText(tmp.File("Stuck.cs"), stuckScript);
    File.WriteAllText(tmp.File("Good.cs"), TestScripts.Background(0.5));
    var evaluator = new GrCis.Scripting.ScriptHost();
    var catalog = new SceneCatalog(evaluator);
    SceneEntry stuck = catalog.AddScriptFile(tmp.File("Stuck.cs"));
    SceneEntry good = catalog.AddScriptFile(tmp.File("Good.cs"));
    return (new DemoController(catalog) { Selected = stuck }, evaluator, stuck, good);
  }

  static void WaitForFile(string path)
  {
    var clock = Stopwatch.StartNew();
    while (!File.Exists(path))
    {
      Assert.True(clock.Elapsed < TimeSpan.FromSeconds(60), "the script never started");
      Thread.Sleep(20);
    }
    Thread.Sleep(100);
  }

  [Fact]
  public async Task Stop_ends_a_script_stuck_while_building_and_the_next_render_works()
  {
    using var tmp = new TempDir();
    string marker = tmp.File("started").Replace("\\", "/", StringComparison.Ordinal);
    (DemoController demo, GrCis.Scripting.ScriptHost evaluator, _, SceneEntry good) = Demo(tmp, StuckScripts.WhileBuilding(marker));
    using (evaluator)
    using (demo)
    {
      string? error = null;
      demo.Error += (_, e) => error = e.Message;

      // RenderAsync hands the script to a worker: the caller gets its task back at once.
      var clock = Stopwatch.StartNew();
      Task<RenderResult?> stuck = demo.RenderAsync();
      Assert.True(clock.Elapsed < TimeSpan.FromSeconds(1), $"RenderAsync blocked its caller for {clock.Elapsed.TotalSeconds:0.0} s");
      WaitForFile(marker);
      Assert.False(stuck.IsCompleted);

      clock.Restart();
      demo.Stop();
      Assert.Null(await stuck.WaitAsync(TimeSpan.FromSeconds(10)));
      Assert.True(clock.Elapsed < TimeSpan.FromSeconds(2), $"stopping took {clock.Elapsed.TotalSeconds:0.0} s");
      Assert.Null(error);

      demo.Selected = good;
      RenderResult next = (await demo.RenderAsync().WaitAsync(TimeSpan.FromSeconds(60)))!;
      Assert.True(next.Succeeded);
      Assert.Equal(0.5, next.Image.GetPixel(3, 3)[0]);
    }
  }

  [Fact]
  public async Task Stop_ends_a_script_texture_stuck_while_rendering()
  {
    using var tmp = new TempDir();
    string marker = tmp.File("started").Replace("\\", "/", StringComparison.Ordinal);
    (DemoController demo, GrCis.Scripting.ScriptHost evaluator, _, _) = Demo(tmp, StuckScripts.WhileRendering(marker));
    using (evaluator)
    using (demo)
    {
      Task<RenderResult?> render = demo.RenderAsync();
      WaitForFile(marker);
      Assert.False(render.IsCompleted);

      var clock = Stopwatch.StartNew();
      demo.Stop();
      RenderResult result = (await render.WaitAsync(TimeSpan.FromSeconds(10)))!;
      Assert.True(clock.Elapsed < TimeSpan.FromSeconds(2), $"stopping took {clock.Elapsed.TotalSeconds:0.0} s");
      Assert.True(result.Cancelled);
      Assert.Null(result.Error);
      Assert.False(demo.IsRendering);
    }
  }
}
