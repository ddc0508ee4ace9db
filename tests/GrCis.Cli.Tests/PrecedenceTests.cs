using System.IO;
using System.Linq;
using Rendering.Imaging;

namespace GrCis.Cli.Tests;

/// <summary>
/// An option given on the command line wins over the script's context value, which wins over the default:
/// image size, supersampling, and the script's image function and renderer objects.
/// </summary>
public class PrecedenceTests
{
  static string Script(TempDirectory dir, string contextLines)
  {
    string path = dir.File("scene.cs");
    File.WriteAllText(path, ScriptCommandTests.SceneBody + contextLines);
    return path;
  }

  static string SummaryLine(CliRun run) => run.Out.Split('\n').First(l => l.StartsWith("wrote ", System.StringComparison.Ordinal));

  [Fact]
  public void Script_size_and_supersampling_beat_the_defaults()
  {
    using var dir = new TempDirectory();
    string s = Script(dir, "context[PropertyName.CTX_WIDTH] = 48;\ncontext[PropertyName.CTX_HEIGHT] = 36;\ncontext[PropertyName.CTX_SUPERSAMPLING] = 4;\n");
    CliRun run = CliRun.Of(dir.Path, "render", s, "-o", "a.png");

    Assert.Equal(0, run.ExitCode);
    Rgb8Image image = PngFile.Load(dir.File("a.png"));
    Assert.Equal((48, 36), (image.Width, image.Height));
    Assert.Contains("48x36, spp 4,", SummaryLine(run));
  }

  [Fact]
  public void Command_line_size_and_spp_beat_the_script()
  {
    using var dir = new TempDirectory();
    string s = Script(dir, "context[PropertyName.CTX_WIDTH] = 48;\ncontext[PropertyName.CTX_HEIGHT] = 36;\ncontext[PropertyName.CTX_SUPERSAMPLING] = 4;\n");
    CliRun run = CliRun.Of(dir.Path, "render", s, "--size", "20x10", "--spp", "1", "-o", "a.png");

    Assert.Equal(0, run.ExitCode);
    Rgb8Image image = PngFile.Load(dir.File("a.png"));
    Assert.Equal((20, 10), (image.Width, image.Height));
    Assert.Contains("20x10, spp 1,", SummaryLine(run));
  }

  [Fact]
  public void Script_size_of_one_dimension_keeps_the_default_other()
  {
    using var dir = new TempDirectory();
    string s = Script(dir, "context[PropertyName.CTX_WIDTH] = 30;\n");
    CliRun run = CliRun.Of(dir.Path, "render", s, "-o", "a.png");
    Assert.Equal(0, run.ExitCode);
    Assert.Contains("30x480,", SummaryLine(run));
  }

  [Fact]
  public void Invalid_script_size_is_a_clear_failure()
  {
    using var dir = new TempDirectory();
    string s = Script(dir, "context[PropertyName.CTX_WIDTH] = -5;\n");
    CliRun run = CliRun.Of(dir.Path, "render", s, "-o", "a.png");
    Assert.Equal(ExitCodes.Failure, run.ExitCode);
    Assert.Contains("scene.cs: the script asks for the image size -5x480", run.Error);
    Assert.False(File.Exists(dir.File("a.png")));
  }

  [Fact]
  public void Script_renderer_is_used_unless_spp_is_given()
  {
    using var dir = new TempDirectory();
    string s = Script(dir, "context[PropertyName.CTX_SYNTHESIZER] = new SupersamplingImageSynthesizer { Supersampling = 9 };\n");

    CliRun scripted = CliRun.Of(dir.Path, "render", s, "--size", "16x12", "-o", "a.png");
    Assert.Equal(0, scripted.ExitCode);
    Assert.Contains("16x12, spp 9,", SummaryLine(scripted));

    CliRun overridden = CliRun.Of(dir.Path, "render", s, "--size", "16x12", "--spp", "4", "-o", "b.png");
    Assert.Equal(0, overridden.ExitCode);
    Assert.Contains("16x12, spp 4,", SummaryLine(overridden));
    Assert.Contains("grcis: note: --spp/--jitter given: the script's renderer SupersamplingImageSynthesizer is not used", overridden.ErrorLines);
  }

  [Fact]
  public void Script_image_function_is_used_and_command_line_switches_apply_to_it()
  {
    using var dir = new TempDirectory();
    // The script's RayTracing casts no shadows: the same image as --no-shadows with the default one.
    string noShadowScript = Script(dir, "RayTracing rt = new RayTracing();\nrt.DoShadows = false;\ncontext[PropertyName.CTX_ALGORITHM] = rt;\n");
    Assert.Equal(0, CliRun.Of(dir.Path, "render", noShadowScript, "--size", "32x24", "-o", "script.png", "-q").ExitCode);
    File.WriteAllText(dir.File("scene.cs"), ScriptCommandTests.SceneBody);
    Assert.Equal(0, CliRun.Of(dir.Path, "render", dir.File("scene.cs"), "--size", "32x24", "-o", "shadows.png", "-q").ExitCode);
    Assert.Equal(0, CliRun.Of(dir.Path, "render", dir.File("scene.cs"), "--size", "32x24", "--no-shadows", "-o", "cli.png", "-q").ExitCode);

    byte[] script = PngFile.Load(dir.File("script.png")).Data;
    Assert.Equal(PngFile.Load(dir.File("cli.png")).Data, script);
    Assert.NotEqual(PngFile.Load(dir.File("shadows.png")).Data, script);
  }

  [Fact]
  public void Custom_image_function_from_the_script_is_used_unless_a_switch_replaces_it()
  {
    using var dir = new TempDirectory();
    string s = Script(dir, """
      context[PropertyName.CTX_ALGORITHM] = new Flat();

      class Flat : IImageFunction
      {
        public double Width { get; set; }
        public double Height { get; set; }
        public long GetSample(double x, double y, double[] color)
        {
          color[0] = 1.0; color[1] = 0.0; color[2] = 1.0;
          return 1L;
        }
      }

      """);
    CliRun flat = CliRun.Of(dir.Path, "render", s, "--size", "8x6", "--gamma", "1", "-o", "flat.png", "-q");
    Assert.Equal(0, flat.ExitCode);
    Assert.All(PngFile.Load(dir.File("flat.png")).Data.Chunk(3), px => Assert.Equal(new byte[] { 255, 0, 255 }, px));

    CliRun replaced = CliRun.Of(dir.Path, "render", s, "--size", "8x6", "--no-reflections", "-o", "r.png", "-q");
    Assert.Equal(0, replaced.ExitCode);
    Assert.Contains(replaced.ErrorLines, l => l.Contains("the script's image function Flat is replaced by RayTracing"));
    Assert.Contains(PngFile.Load(dir.File("r.png")).Data.Chunk(3), px => px[1] > 0);
  }
}
