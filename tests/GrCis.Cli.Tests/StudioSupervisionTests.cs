using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Net;
using System.Net.Http;
using System.Threading;
using System.Threading.Tasks;

namespace GrCis.Cli.Tests;

/// <summary>
/// <c>grcis studio</c> survives its scripts (issue 40): a script that overflows the stack, runs out of memory or ignores
/// Stop ends at most the studio process, which the supervisor restarts; the page is told in one sentence, another page's
/// requests are answered during and after, and the next render is the image <c>grcis render</c> makes.
/// </summary>
public sealed class StudioSupervisionTests : IDisposable
{
  readonly TempDirectory dir = new();

  public StudioSupervisionTests()
  {
    File.Copy(RepoPaths.Script("TwoSpheres.cs"), dir.File("TwoSpheres.cs"));
    // A recursion through code the compiler writes (a record's equality), which the script host's recursion guard does not see.
    File.WriteAllText(dir.File("Overflow.cs"), """
      var a = new Link(1); a.Next = a;
      var b = new Link(1); b.Next = b;
      Console.WriteLine(a.Equals(b));
      record Link(int Value) { public Link? Next { get; set; } }
      """);
    // Spins in library code (no loop of the script's for the host to instrument): Stop cannot reach it.
    File.WriteAllText(dir.File("SpinTexture.cs"), """
      Sphere s = new Sphere();
      s.SetAttribute(PropertyName.TEXTURE, new Spinner());
      CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
      root.InsertChild(s, Matrix4d.Identity);
      scene.Intersectable = root;
      scene.BackgroundColor = new double[] { 0.0, 0.0, 0.0 };
      scene.Camera = new StaticCamera(new Vector3d(0.0, 0.0, -5.0), new Vector3d(0.0, 0.0, 1.0), 50.0);
      scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
      scene.Sources.Add(new AmbientLightSource(0.8));
      class Spinner : ITexture
      {
        public long Apply(Intersection inter) { System.Threading.SpinWait.SpinUntil(() => false); return 0L; }
      }
      """);
    File.WriteAllText(dir.File("SpinBuild.cs"), "System.Threading.SpinWait.SpinUntil(() => false);\n");
    File.WriteAllText(dir.File("Alloc.cs"), """
      var kept = new System.Collections.Generic.List<byte[]>();
      while (true) kept.Add(new byte[16 << 20]);
      """);
  }

  public void Dispose() => dir.Dispose();

  [Fact]
  public async Task A_stack_overflow_restarts_the_render_process_and_other_pages_are_answered_throughout()
  {
    using var studio = new SupervisedStudio(dir.Path);
    using HttpClient other = studio.NewPage();
    using var done = new CancellationTokenSource();
    Task<List<HttpStatusCode>> otherPage = AskAgainAndAgain(other, done.Token);

    await studio.Render("Overflow");
    var status = await studio.WaitFor(s => SupervisedStudio.Generation(s) == 1, 90, "a new render process");
    Assert.Equal("The render process overflowed its stack; the studio restarted it.", SupervisedStudio.Error(status));
    Assert.Equal("idle", status.GetProperty("phase").GetString());

    await ItRendersAsGrcisRenderDoes(studio);
    await done.CancelAsync();
    List<HttpStatusCode> answers = await otherPage;
    Assert.True(answers.Count > 5, $"only {answers.Count} answers");
    Assert.All(answers, a => Assert.Equal(HttpStatusCode.OK, a));
  }

  [Fact]
  public async Task A_texture_that_ignores_stop_ends_the_render_process_after_the_grace_time()
  {
    using var studio = new SupervisedStudio(dir.Path);
    await studio.Render("SpinTexture");
    await studio.WaitFor(s => s.GetProperty("phase").GetString() == "rendering", 90, "the render");
    await Task.Delay(500);

    var clock = System.Diagnostics.Stopwatch.StartNew();
    using (HttpResponseMessage stop = await studio.Client.PostAsync("api/stop", null))
      Assert.Equal(HttpStatusCode.NoContent, stop.StatusCode);
    Assert.False((await studio.Status()).GetProperty("rendering").GetBoolean());
    var status = await studio.WaitFor(s => SupervisedStudio.Generation(s) == 1, 60, "a new render process");
    Assert.Equal("The render process did not stop within 2 s and was ended; the studio restarted it.", SupervisedStudio.Error(status));
    Assert.True(clock.Elapsed >= TimeSpan.FromSeconds(2), $"ended after {clock.Elapsed.TotalSeconds:0.0} s, before the grace time");

    await ItRendersAsGrcisRenderDoes(studio);
  }

  [Fact]
  public async Task A_scene_build_that_ignores_stop_ends_the_render_process_and_a_finished_stop_does_not()
  {
    using var studio = new SupervisedStudio(dir.Path);
    // A render that obeys Stop is not ended: the process (its generation) stays.
    await studio.Render("TwoSpheres", 640, 480);
    await studio.WaitFor(s => s.GetProperty("phase").GetString() == "rendering", 90, "the render");
    using (HttpResponseMessage stop = await studio.Client.PostAsync("api/stop", null))
      Assert.Equal(HttpStatusCode.NoContent, stop.StatusCode);
    await Task.Delay(3500);
    Assert.Equal(0, SupervisedStudio.Generation(await studio.Status()));

    await studio.Render("SpinBuild");
    await Task.Delay(TimeSpan.FromSeconds(6));   // compiled (the scripts' cache is warm after the first run) and spinning
    using (HttpResponseMessage stop = await studio.Client.PostAsync("api/stop", null))
      Assert.Equal(HttpStatusCode.NoContent, stop.StatusCode);
    var status = await studio.WaitFor(s => SupervisedStudio.Generation(s) == 1, 60, "a new render process");
    Assert.Equal("The render process did not stop within 2 s and was ended; the studio restarted it.", SupervisedStudio.Error(status));
    await ItRendersAsGrcisRenderDoes(studio);
  }

  [Fact]
  public async Task A_script_over_the_memory_limit_fails_naming_its_line_and_the_studio_renders_on()
  {
    using var studio = new SupervisedStudio(dir.Path, "--memory-limit", "600M");
    await studio.Render("Alloc");
    var status = await studio.WaitFor(s => SupervisedStudio.Error(s) != null, 120, "the script's error");
    string error = SupervisedStudio.Error(status)!;
    // Either the allocation over the limit failed in the script (the process lives on), or the process died of it.
    if (SupervisedStudio.Generation(status) == 0)
      Assert.Matches(@"Alloc\.cs\(2,\d+\): runtime error: OutOfMemoryException", error);
    else
      Assert.Equal("The render process ran out of memory; the studio restarted it.", error);
    await ItRendersAsGrcisRenderDoes(studio);
  }

  [Fact]
  public void A_bad_memory_limit_is_a_usage_error_before_anything_listens()
  {
    (int code, string output, string error) = GrcisProcess.Run(dir.Path, "studio", "--no-open", "--memory-limit", "lots");
    Assert.Equal(2, code);
    Assert.Equal("", output);
    Assert.Contains("invalid --memory-limit 'lots'", error);
  }

  /// <summary>The next render of TwoSpheres: its image is byte for byte the PNG of <c>grcis render</c>.</summary>
  async Task ItRendersAsGrcisRenderDoes(SupervisedStudio studio)
  {
    await studio.Render("TwoSpheres", 64, 48);
    var status = await studio.WaitFor(s => s.GetProperty("phase").GetString() == "idle" && s.GetProperty("fraction").GetDouble() == 1.0,
                                      120, "the render of TwoSpheres");
    Assert.Null(SupervisedStudio.Error(status));
    byte[] shown = await studio.Client.GetByteArrayAsync("api/image.png");

    string png = dir.File("cli.png");
    (int code, _, string error) = GrcisProcess.Run(dir.Path, "render", dir.File("TwoSpheres.cs"), "--size", "64x48", "--spp", "1", "-t", "2",
                                                   "-q", "-o", png);
    Assert.True(code == 0, error);
    Assert.Equal(File.ReadAllBytes(png), shown);
  }

  /// <summary>Another page asking for the scene list every 100 ms until told to stop: the status of each answer.</summary>
  static async Task<List<HttpStatusCode>> AskAgainAndAgain(HttpClient page, CancellationToken done)
  {
    var answers = new List<HttpStatusCode>();
    while (!done.IsCancellationRequested)
    {
      using (HttpResponseMessage r = await page.GetAsync("api/scenes", CancellationToken.None))
        answers.Add(r.StatusCode);
      try
      {
        await Task.Delay(100, done);
      }
      catch (OperationCanceledException)
      {
      }
    }
    return answers;
  }
}
