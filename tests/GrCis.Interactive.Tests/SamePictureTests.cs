using System.IO;
using System.Threading;
using System.Threading.Tasks;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;
using Rendering.Observation;
using GrCis.Hosting;

namespace GrCis.Interactive.Tests;

/// <summary>
/// One picture whatever renders it: <c>grcis render</c>, the demo's session and a render with a ray observer
/// attached give the same bytes, also for a script whose own ray tracer sets the opt-in switches
/// (TransparentShadows, FresnelRefraction) that a copied tracer used to lose; and the demo renders the
/// script's own tracer on the fast path.
/// </summary>
public class SamePictureTests
{
  const string GlassScript = """
    // Glass sphere on a checkered floor, rendered by the script's own ray tracer with both opt-in switches.
    CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 0.5, 0.5, 0.5 }, 0.1, 0.6, 0.3, 16));
    Sphere s = new Sphere();
    s.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 0.0, 0.2, 0.1 }, 0.05, 0.05, 0.1, 128) { Kt = 0.9, n = 1.5 });
    root.InsertChild(s, Matrix4d.Identity);
    Plane pl = new Plane();
    pl.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(1.0, 1.0, new double[] { 1.0, 1.0, 1.0 }));
    root.InsertChild(pl, Matrix4d.CreateRotationX(-Math.PI / 2) * Matrix4d.CreateTranslation(0, -1, 0));
    scene.Intersectable = root;
    scene.BackgroundColor = new double[] { 0.1, 0.2, 0.3 };
    scene.Camera = new StaticCamera(new Vector3d(0, 0.5, -5), new Vector3d(0, -0.1, 1), 45.0);
    scene.Sources = new LinkedList<ILightSource>();
    scene.Sources.Add(new AmbientLightSource(0.6));
    scene.Sources.Add(new PointLightSource(new Vector3d(-5, 5, -5), 1.0));
    context[PropertyName.CTX_ALGORITHM] = new RayTracing { TransparentShadows = true, FresnelRefraction = true };
    """;

  /// <summary>Counts what it is told, across threads.</summary>
  sealed class Tally : RayObserver
  {
    public long Shaded, Shadows, Refracted;

    public override void BeginRay(RayKind kind, int depth, in Vector3d origin, in Vector3d direction)
    {
      Interlocked.Increment(ref Shaded);
      if (kind == RayKind.Refracted)
        Interlocked.Increment(ref Refracted);
    }

    public override void ShadowRay(in Vector3d origin, in Vector3d direction, bool blocked) => Interlocked.Increment(ref Shadows);
  }

  [Fact]
  public async Task Cli_demo_and_observed_render_give_the_same_bytes_for_a_script_with_opt_in_switches()
  {
    using var tmp = new TempDir();
    string script = tmp.File("Glass.cs");
    File.WriteAllText(script, GlassScript);
    var output = new StringWriter();
    var error = new StringWriter();
    var env = new GrCis.Cli.CliEnvironment(output, error) { WorkingDirectory = tmp.Path };
    Assert.True(GrCis.Cli.Program.Run(["render", script, "-o", "cli.pfm", "--size", "80x60", "--spp", "4", "--seed", "3", "--threads", "2", "-q"], env) == 0,
      error.ToString());
    FloatImage cli = ImageFile.Load(tmp.File("cli.pfm"));

    using var evaluator = new GrCis.Scripting.ScriptHost();
    var catalog = new SceneCatalog(evaluator);
    SceneEntry entry = catalog.AddScriptFile(script);
    var settings = new RenderSettings { Width = 80, Height = 60, SamplesPerPixel = 4, Seed = 3, Threads = 3, TileSize = 16 };
    using var demo = new DemoController(catalog) { Settings = settings, Selected = entry };
    RenderResult result = (await demo.RenderAsync())!;
    Assert.True(result.Succeeded, result.Error?.Message);
    Assert.Equal(cli.Data, result.Image.Data);

    // The demo rendered the script's own tracer (both switches kept), prepared for the fast path, and counted its rays.
    var tracer = Assert.IsType<RayTracing>(result.Job.ImageFunction);
    Assert.True(tracer.TransparentShadows && tracer.FresnelRefraction);
    Assert.NotNull(tracer.LastPrepared);
    Assert.True(result.Statistics.Rays > result.Statistics.Intersections && result.Statistics.Intersections > 0,
      $"{result.Statistics.Rays} rays, {result.Statistics.Intersections} hits");

    // The same job with an observer attached: same bytes, and the observer saw every counted ray.
    var tally = new Tally();
    var context = new RenderContext { Observer = tally };
    FloatImage observed = TileRenderer.Render(result.Job.Scene, result.Job.ImageFunction, result.Job.Renderer, result.Job.Options, null, default, context);
    Assert.Equal(cli.Data, observed.Data);
    Assert.Equal(context.Rays, tally.Shaded + tally.Shadows);
    Assert.True(tally.Refracted > 0 && tally.Shadows > 0);
  }
}
