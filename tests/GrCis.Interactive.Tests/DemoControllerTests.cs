using System;
using System.IO;
using System.Threading.Tasks;
using Rendering.Imaging;
using Rendering.Observation;
using GrCis.Hosting;

namespace GrCis.Interactive.Tests;

public class DemoControllerTests
{
  [Fact]
  public async Task Editing_the_watched_script_re_renders_with_the_new_content()
  {
    using var tmp = new TempDir();
    string path = tmp.File("Watched.cs");
    File.WriteAllText(path, TestScripts.Background(0.25));
    using var evaluator = new GrCis.Scripting.ScriptHost();
    var catalog = new SceneCatalog(evaluator);
    using var demo = new DemoController(catalog) { WatchDebounce = TimeSpan.FromMilliseconds(100) };
    demo.Selected = catalog.AddScriptFile(path);

    RenderResult first = (await demo.RenderAsync())!;
    Assert.Equal(0.25, first.Image.GetPixel(5, 5)[0]);

    var rerendered = new TaskCompletionSource<RenderResult>(TaskCreationOptions.RunContinuationsAsynchronously);
    demo.RenderCompleted += (_, e) => rerendered.TrySetResult(e.Result);
    demo.WatchScript = true;
    File.WriteAllText(path, TestScripts.Background(0.75));

    RenderResult second = await rerendered.Task.WaitAsync(TimeSpan.FromSeconds(20));
    Assert.True(second.Succeeded);
    Assert.Equal(0.75, second.Image.GetPixel(5, 5)[0]);
    Assert.Equal(2, demo.History.Items.Count);
  }

  [Fact]
  public async Task Render_probe_views_history_and_save()
  {
    using var tmp = new TempDir();
    var catalog = new SceneCatalog();
    catalog.AddBuiltIn("Mirror ball", _ => TestScenes.SphereOnPlane());
    using var demo = new DemoController(catalog) { Settings = new RenderSettings { Width = 33, Height = 33 } };
    demo.Selected = catalog.Entries[0];
    int previews = 0;
    demo.PreviewReady += (_, _) => previews++;

    RenderResult r = (await demo.RenderAsync())!;
    Assert.True(r.Succeeded);
    Assert.True(previews >= 2);
    Assert.Same(r, demo.LastResult);

    ProbeResult probe = demo.Probe(16, 16);
    Assert.Equal(r.Image.GetPixel(16, 16), probe.PixelColor);
    Assert.Equal(RayKind.Primary, probe.Rays!.Kind);
    Assert.Equal(4.0, demo.ComputeExtraViews().DepthAt(16, 16), 9);

    Assert.True(demo.SaveImage(tmp.File("out.png")));
    Assert.True(PngFile.Load(tmp.File("out.png")).ContentEquals(r.ToRgb8()));
    string? error = null;
    demo.Error += (_, e) => error = e.Message;
    Assert.False(demo.SaveImage(tmp.File("no/such/dir/out.png")));
    Assert.NotNull(error);
  }

  [Fact]
  public async Task A_broken_script_is_reported_not_thrown()
  {
    using var tmp = new TempDir();
    File.WriteAllText(tmp.File("Bad.cs"), "// first\nnonsense here");
    using var evaluator = new GrCis.Scripting.ScriptHost();
    var catalog = new SceneCatalog(evaluator);
    using var demo = new DemoController(catalog) { Selected = catalog.AddScriptFile(tmp.File("Bad.cs")) };
    DemoErrorEventArgs? error = null;
    demo.Error += (_, e) => error = e;
    Assert.Null(await demo.RenderAsync());
    Assert.Contains("Bad.cs", error!.Message);
    // The places come as objects (a front end marks them without reading the message back).
    Assert.NotEmpty(error.Diagnostics);
    Assert.All(error.Diagnostics, d => Assert.Equal(Path.GetFullPath(tmp.File("Bad.cs")), d.Path));
    Assert.Contains(error.Diagnostics, d => d.IsError && d.Line == 2);
  }

  [Fact]
  public async Task A_script_class_that_throws_while_rendering_is_reported_with_its_file_and_line_as_grcis_reports_it()
  {
    using var tmp = new TempDir();
    string path = tmp.File("Throws.cs");
    File.WriteAllText(path, """
      scene.Intersectable = new Sphere();
      scene.Camera = new StaticCamera(new Vector3d(0, 0, -5), new Vector3d(0, 0, 1), 40);
      scene.Sources = new List<ILightSource> { new PointLightSource(new Vector3d(-5, 5, -5), 1.0) };
      context[PropertyName.CTX_ALGORITHM] = new Failing();

      class Failing : RayTracing
      {
        public override long GetSample (double x, double y, double[] color) =>
          throw new InvalidOperationException("homework not finished");
      }
      """);
    using var host = new GrCis.Scripting.ScriptHost();
    var catalog = new SceneCatalog(host);
    using var demo = new DemoController(catalog) { Settings = new RenderSettings { Width = 8, Height = 6 } };
    demo.Selected = catalog.AddScriptFile(path);
    DemoErrorEventArgs? error = null;
    demo.Error += (_, e) => error = e;

    RenderResult r = (await demo.RenderAsync())!;

    Assert.False(r.Succeeded);
    Assert.Equal($"{path}(9,5): runtime error: InvalidOperationException: homework not finished", error!.Message);
    Assert.Empty(demo.History.Items);
    GrCis.Scripting.ScriptDiagnostic d = Assert.Single(error.Diagnostics);
    Assert.Equal((path, 9, 5, "error", "InvalidOperationException", "homework not finished"), (d.Path, d.Line, d.Column, d.Severity, d.Id, d.Message));
  }
}
