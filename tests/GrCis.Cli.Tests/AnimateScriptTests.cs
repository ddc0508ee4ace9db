using System;
using System.IO;
using System.Linq;
using Rendering.Imaging;

namespace GrCis.Cli.Tests;

/// <summary><c>grcis animate</c> with scene scripts: the preprocessing protocol, the script's range, motion blur.</summary>
public class AnimateScriptTests
{
  /// <summary>
  /// Counts its preprocessing calls in the context and logs every call to the file named by its
  /// parameter; the background's blue is 0.25 × (preprocessing calls), so a frame shows whether
  /// the preprocessing ran once and its result reached it. A sphere orbits so frames differ.
  /// </summary>
  const string CountingScript = """
    string log = param.Trim();
    if (Util.TryParseBool(context, PropertyName.CTX_PREPROCESSING))
    {
      int calls = 0;
      Util.TryParse(context, "preprocessCalls", ref calls);
      context["preprocessCalls"] = calls + 1;
      context["simulation"] = 0.25 * (calls + 1);
      System.IO.File.AppendAllText(log, "preprocess\n");
      return;
    }
    System.IO.File.AppendAllText(log, "regular\n");
    double blue = (double)context["simulation"];

    context[PropertyName.CTX_START_ANIM] = 1.0;
    context[PropertyName.CTX_END_ANIM] = 2.0;
    context[PropertyName.CTX_FPS] = 5.0;
    context[PropertyName.CTX_WIDTH] = 24;
    context[PropertyName.CTX_HEIGHT] = 18;

    if (scene is ITimeDependent animated)
    {
      animated.Start = 1.0;
      animated.End = 2.0;
    }
    CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 1.0, 0.6, 0.1 }, 0.1, 0.6, 0.4, 32));
    scene.Intersectable = root;
    root.InsertChild(new Sphere(), Matrix4d.CreateTranslation(1.5, 0.0, 0.0));
    scene.BackgroundColor = new double[] { 0.0, 0.0, blue };
    AnimatedCamera cam = new AnimatedCamera(new Vector3d(0.0, 0.0, 0.0), new Vector3d(0.0, 1.0, -8.0), 50.0);
    cam.Start = 1.0;
    cam.End = 2.0;
    scene.Camera = cam;
    scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
    scene.Sources.Add(new AmbientLightSource(0.8));
    scene.Sources.Add(new PointLightSource(new Vector3d(-5.0, 4.0, -3.0), 1.2));
    """;

  [Fact]
  public void Preprocessing_runs_once_per_animation_and_reaches_every_frame()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("Counting.cs"), CountingScript);
    string log = dir.File("calls.log");
    CliRun run = CliRun.Of(dir.Path, "animate", "Counting.cs", "-o", "f/c##.png", "--param", log, "--gamma", "1", "--parallel", "frames", "--threads", "2");

    Assert.True(run.ExitCode == 0, run.Error);
    Assert.Equal(new[] { "preprocess", "regular" }, File.ReadAllLines(log));
    // The script's range (1 to 2 s at 5 fps) and size (24x18) apply.
    string[] frames = Directory.GetFiles(dir.File("f")).Select(Path.GetFileName).Order(StringComparer.Ordinal).ToArray()!;
    Assert.Equal(Enumerable.Range(0, 6).Select(k => $"c{k:D2}.png"), frames);
    var images = frames.Select(f => PngFile.Load(dir.File("f/" + f))).ToArray();
    Assert.All(images, img => Assert.Equal((24, 18), (img.Width, img.Height)));
    // Corner pixel is background: blue = 0.25 (one preprocessing call) in every frame.
    Assert.All(images, img => Assert.Equal((0, 0, (int)(0.25 * 255)), ((int)img.GetPixel(0, 0).R, (int)img.GetPixel(0, 0).G, (int)img.GetPixel(0, 0).B)));
    Assert.False(images[0].ContentEquals(images[2]), "the camera orbits (once over the range: the last frame is the first again)");
  }

  [Fact]
  public void Command_line_range_overrides_the_script_context()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("Counting.cs"), CountingScript);
    CliRun run = CliRun.Of(dir.Path, "animate", "Counting.cs", "-o", "f#.png", "--param", dir.File("log"), "--fps", "2", "--size", "8x6");
    Assert.True(run.ExitCode == 0, run.Error);
    Assert.Equal(new[] { "f0.png", "f1.png", "f2.png" }, Directory.GetFiles(dir.Path, "*.png").Select(Path.GetFileName).Order(StringComparer.Ordinal));
    Assert.Equal(8, PngFile.Load(dir.File("f0.png")).Width);
  }

  [Fact]
  public void Orbit_script_with_a_shutter_is_blurred_and_deterministic()
  {
    string orbit = RepoPaths.Script("Orbit.cs");
    using var dir = new TempDirectory();
    string[] common = { "animate", orbit, "--frames", "5", "--size", "48x36", "--spp", "9", "-q" };
    Assert.Equal(0, CliRun.Of(dir.Path, [.. common, "-o", "sharp/o#.png"]).ExitCode);
    CliRun blurred = CliRun.Of(dir.Path, [.. common, "-o", "blur/o#.png", "--shutter", "1"]);
    Assert.True(blurred.ExitCode == 0, blurred.Error);
    Assert.Equal(0, CliRun.Of(dir.Path, [.. common, "-o", "again/o#.png", "--shutter", "1", "--threads", "1"]).ExitCode);

    Rgb8Image sharp = PngFile.Load(dir.File("sharp/o5.png")), blur = PngFile.Load(dir.File("blur/o5.png"));
    int differing = Enumerable.Range(0, sharp.Data.Length).Count(i => Math.Abs(sharp.Data[i] - blur.Data[i]) > 8);
    Assert.True(differing > sharp.Data.Length / 20, $"only {differing} channel values differ noticeably");
    Assert.True(blur.ContentEquals(PngFile.Load(dir.File("again/o5.png"))), "motion blur is deterministic");
  }
}
