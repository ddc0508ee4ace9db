using System.IO;
using System.Linq;
using System.Threading.Tasks;
using Rendering;
using GrCis.Hosting;

namespace GrCis.Interactive.Tests;

/// <summary>
/// The fields show the script's own values once a scene is chosen, marked as the script's; a value the user changes wins,
/// exactly as an option of <c>grcis render</c> / <c>grcis animate</c> does (the one precedence rule).
/// </summary>
public class HonestSettingsTests
{
  // Its own size, supersampling, algorithm and animation range.
  const string Script = """
    Rendering.Scenes.FiveBalls(scene);
    context[PropertyName.CTX_WIDTH] = 40;
    context[PropertyName.CTX_HEIGHT] = 30;
    context[PropertyName.CTX_SUPERSAMPLING] = 4;
    context[PropertyName.CTX_ALGORITHM] = new DistributedRayTracing();
    context[PropertyName.CTX_START_ANIM] = 0.0;
    context[PropertyName.CTX_END_ANIM] = 2.0;
    context[PropertyName.CTX_FPS] = 5.0;
    """;

  static byte[] Cli(TempDir tmp, string script, string output, params string[] more)
  {
    var error = new StringWriter();
    var env = new GrCis.Cli.CliEnvironment(new StringWriter(), error) { WorkingDirectory = tmp.Path };
    string[] args = new[] { "render", script, "-o", output, "--threads", "2", "-q" }.Concat(more).ToArray();
    Assert.True(GrCis.Cli.Program.Run(args, env) == 0, error.ToString());
    return File.ReadAllBytes(tmp.File(output));
  }

  static async Task<byte[]> Demo(DemoController demo, TempDir tmp, string output)
  {
    RenderResult? result = await demo.RenderAsync();
    Assert.True(result is { Succeeded: true }, result?.Error?.Message);
    Assert.True(demo.SaveImage(tmp.File(output)));
    return File.ReadAllBytes(tmp.File(output));
  }

  [Fact]
  public async Task Choosing_a_scene_shows_the_scripts_own_values_marked_as_the_scripts()
  {
    using var tmp = new TempDir();
    File.WriteAllText(tmp.File("Own.cs"), Script);
    using var scripts = new GrCis.Scripting.ScriptHost();
    var catalog = new SceneCatalog(scripts);
    catalog.AddBuiltIn("Plane", _ => TestScenes.PlaneAt(5));
    using var demo = new DemoController(catalog) { Settings = new RenderSettings { Width = 640, Height = 480 }, Selected = catalog.AddScriptFile(tmp.File("Own.cs")) };

    SceneOverrides values = await demo.ReadScriptValuesAsync();

    Assert.Equal((40, 30, 4, "DistributedRayTracing"), (values.Width, values.Height, values.Supersampling, values.Algorithm));
    Assert.Equal((0.0, 2.0, 5.0), (values.Start, values.End, values.Fps));
    Assert.Same(values, demo.Selected!.Overrides);
    RenderSettings shown = demo.ShownSettings();
    Assert.Equal((40, 30, 4), (shown.Width, shown.Height, shown.SamplesPerPixel));
    Assert.True(demo.IsScriptValue(Setting.Size) && demo.IsScriptValue(Setting.SamplesPerPixel) && demo.IsScriptValue(Setting.Algorithm));

    // Changed by the user: the field shows the user's value, no longer the script's.
    demo.Given = GivenSettings.Size;
    Assert.Equal((640, 480, 4), (demo.ShownSettings().Width, demo.ShownSettings().Height, demo.ShownSettings().SamplesPerPixel));
    Assert.False(demo.IsScriptValue(Setting.Size));
    Assert.True(demo.IsScriptValue(Setting.SamplesPerPixel));
    demo.Algorithm = RenderAlgorithm.Path;
    Assert.False(demo.IsScriptValue(Setting.Algorithm));

    // A built-in scene sets nothing: every field is the user's.
    demo.Selected = catalog.Find("Plane");
    Assert.True((await demo.ReadScriptValuesAsync()).IsEmpty);
    Assert.False(demo.IsScriptValue(Setting.Size));
  }

  [Fact]
  public async Task A_value_the_user_changes_wins_over_the_scripts_as_a_command_line_option_does()
  {
    using var tmp = new TempDir();
    string script = tmp.File("Own.cs");
    File.WriteAllText(script, Script);
    using var scripts = new GrCis.Scripting.ScriptHost();
    var catalog = new SceneCatalog(scripts);
    using var demo = new DemoController(catalog)
    {
      Settings = new RenderSettings { Width = 24, Height = 18, SamplesPerPixel = 1, Threads = 2 },
      Selected = catalog.AddScriptFile(script),
    };

    // Untouched fields: the script's 40x30 at 4 spp, the image of `grcis render Own.cs`.
    byte[] own = await Demo(demo, tmp, "own.png");
    Assert.Equal((40, 30), (demo.LastJob!.Width, demo.LastJob.Height));
    Assert.Equal(Cli(tmp, script, "cli-own.png"), own);

    // The user changed the size: theirs wins, the script's supersampling stays (`--size 24x18`).
    demo.Given = GivenSettings.Size;
    byte[] sized = await Demo(demo, tmp, "sized.png");
    Assert.Equal((24, 18, 4), (demo.LastJob!.Width, demo.LastJob.Height, demo.LastJob.Settings.SamplesPerPixel));
    Assert.Equal(Cli(tmp, script, "cli-sized.png", "--size", "24x18"), sized);

    // And the supersampling (`--size 24x18 --spp 1`).
    demo.Given = GivenSettings.Size | GivenSettings.SamplesPerPixel;
    Assert.Equal(Cli(tmp, script, "cli-both.png", "--size", "24x18", "--spp", "1"), await Demo(demo, tmp, "both.png"));
    Assert.Equal(1, demo.LastJob!.Settings.SamplesPerPixel);
  }

  [Fact]
  public void An_animation_range_the_user_gives_wins_and_the_rest_is_the_scripts()
  {
    using var tmp = new TempDir();
    File.WriteAllText(tmp.File("Own.cs"), Script);
    using var scripts = new GrCis.Scripting.ScriptHost();
    var catalog = new SceneCatalog(scripts);
    using var demo = new DemoController(catalog) { Selected = catalog.AddScriptFile(tmp.File("Own.cs")) };

    AnimationTimeline script = demo.CreateAnimation().Timeline;
    Assert.Equal((0.0, 2.0, 5.0, 11), (script.Start, script.End, script.Fps, script.FrameCount));

    // From 0, to 1, 4 fps: five frames of 0–1 s, not the script's range (as grcis animate --from 0 --to 1 --fps 4).
    AnimationTimeline user = demo.CreateAnimation(0.0, 1.0, 4.0).Timeline;
    Assert.Equal((0.0, 1.0, 4.0, 5), (user.Start, user.End, user.Fps, user.FrameCount));

    // Only the frame rate given: the script's range at the user's rate.
    AnimationTimeline rate = demo.CreateAnimation(fps: 2.0).Timeline;
    Assert.Equal((0.0, 2.0, 2.0, 5), (rate.Start, rate.End, rate.Fps, rate.FrameCount));
  }
}
