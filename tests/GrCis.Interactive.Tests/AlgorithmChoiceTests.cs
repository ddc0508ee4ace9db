using System.IO;
using System.Linq;
using System.Threading.Tasks;
using Rendering;
using Rendering.Distributed;
using Rendering.Imaging;
using GrCis.Hosting;

namespace GrCis.Interactive.Tests;

/// <summary>
/// The demo's algorithm choice (<see cref="DemoController.Algorithm"/>): a chosen one replaces the script's function
/// exactly as <c>grcis render --algorithm</c> does (same bytes); none keeps the script's own choice.
/// </summary>
public class AlgorithmChoiceTests
{
  // Five balls, rendered by the script's own distributed ray tracer.
  const string Script = "Rendering.Scenes.FiveBalls(scene);\ncontext[PropertyName.CTX_ALGORITHM] = new DistributedRayTracing();\n";

  static readonly RenderSettings Small = new() { Width = 40, Height = 30, SamplesPerPixel = 4, Seed = 3, Threads = 2 };

  /// <summary>Runs <c>grcis render</c> in-process with the settings of <see cref="Small"/>; returns the file's path.</summary>
  static string Cli(TempDir tmp, string script, string output, params string[] more)
  {
    var error = new StringWriter();
    var env = new GrCis.Cli.CliEnvironment(new StringWriter(), error) { WorkingDirectory = tmp.Path };
    string[] args = new[] { "render", script, "-o", output, "--size", "40x30", "--spp", "4", "--seed", "3", "--threads", "2", "-q" }.Concat(more).ToArray();
    Assert.True(GrCis.Cli.Program.Run(args, env) == 0, error.ToString());
    return tmp.File(output);
  }

  static async Task<RenderResult> Render(DemoController demo)
  {
    RenderResult? result = await demo.RenderAsync();
    Assert.NotNull(result);
    Assert.True(result.Succeeded, result.Error?.Message);
    return result;
  }

  [Fact]
  public async Task A_chosen_algorithm_gives_grcis_render_algorithm_bytes_and_none_keeps_the_scripts_choice()
  {
    using var tmp = new TempDir();
    string script = tmp.File("Balls.cs");
    File.WriteAllText(script, Script);
    using var evaluator = new GrCis.Scripting.ScriptHost();
    var catalog = new SceneCatalog(evaluator);
    using var demo = new DemoController(catalog) { Settings = Small, Selected = catalog.AddScriptFile(script) };

    // Null, the default: the script's DistributedRayTracing, the image `grcis render` gives without --algorithm.
    Assert.Null(demo.Algorithm);
    RenderResult own = await Render(demo);
    Assert.IsType<DistributedRayTracing>(own.Job.ImageFunction);
    Assert.Equal(ImageFile.Load(Cli(tmp, script, "own.pfm")).Data, own.Image.Data);

    // Path: the script's function replaced by PathTracing (and said so), the bytes of `grcis render --algorithm path`.
    demo.Algorithm = RenderAlgorithm.Path;
    RenderResult path = await Render(demo);
    Assert.IsType<PathTracing>(path.Job.ImageFunction);
    Assert.Contains(path.Job.Notes, n => n.Contains("DistributedRayTracing") && n.Contains("PathTracing"));
    Assert.Equal(ImageFile.Load(Cli(tmp, script, "path.pfm", "--algorithm", "path")).Data, path.Image.Data);
    Assert.True(demo.SaveImage(tmp.File("demo.png")));
    Assert.Equal(File.ReadAllBytes(Cli(tmp, script, "path.png", "--algorithm", "path")), File.ReadAllBytes(tmp.File("demo.png")));
    Assert.NotEqual(own.Image.Data, path.Image.Data);

    // Back to the scene's choice: the script's function again, the same image as before.
    demo.Algorithm = null;
    RenderResult again = await Render(demo);
    Assert.IsType<DistributedRayTracing>(again.Job.ImageFunction);
    Assert.Equal(own.Image.Data, again.Image.Data);
  }

  [Fact]
  public async Task A_chosen_algorithm_renders_a_built_in_scene_and_an_animation_with_it()
  {
    var catalog = new SceneCatalog();
    catalog.AddBuiltIn("Mirror ball", _ => TestScenes.SphereOnPlane());
    using var demo = new DemoController(catalog) { Settings = Small, Selected = catalog.Entries[0] };

    RenderResult whitted = await Render(demo);
    Assert.IsType<RayTracing>(whitted.Job.ImageFunction);

    demo.Algorithm = RenderAlgorithm.Distributed;
    RenderResult distributed = await Render(demo);
    Assert.IsType<DistributedRayTracing>(distributed.Job.ImageFunction);
    Assert.Equal(RenderAlgorithm.Distributed, distributed.Job.Settings.Algorithm);
    Assert.IsType<DistributedRayTracing>(demo.CreateAnimation(0.0, 1.0, 1.0).Job.ImageFunction);
  }
}
