using System.IO;
using System.Linq;
using System.Threading;
using Rendering;
using Rendering.Imaging;

namespace GrCis.Cli.Tests;

public class RenderCommandTests
{
  [Fact]
  public void Render_default_scene_writes_a_png_of_the_requested_size()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", "--size", "64x48", "-o", "out.png", "--threads", "2");

    Assert.Equal(0, run.ExitCode);
    Assert.Equal("", run.Error.Split('\n').FirstOrDefault(l => l.StartsWith("grcis: error")) ?? "");
    Rgb8Image image = PngFile.Load(dir.File("out.png"));
    Assert.Equal(64, image.Width);
    Assert.Equal(48, image.Height);
    Assert.True(image.Data.Distinct().Count() > 10, "the render should not be a flat image");
    Assert.Equal(new[] { dir.File("out.png") }, dir.AllFiles());
  }

  [Fact]
  public void Final_line_names_file_size_spp_and_time()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", "--size", "40x30", "--spp", "4", "-o", "s.png");

    Assert.Equal(0, run.ExitCode);
    string line = Assert.Single(run.Out.Split('\n', System.StringSplitOptions.RemoveEmptyEntries));
    Assert.Contains(dir.File("s.png"), line);
    Assert.Contains("40x30", line);
    Assert.Contains("spp 4", line);
    Assert.Matches(@"\d+\.\d\d s", line);
  }

  [Fact]
  public void Redirected_progress_is_plain_lines_up_to_100_percent()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", "--size", "96x64", "-o", "p.png");

    Assert.Equal(0, run.ExitCode);
    Assert.Contains(run.ErrorLines, l => l.EndsWith("100% (6/6 tiles)"));
    Assert.DoesNotContain('\u001b', run.Error);
  }

  [Fact]
  public void Quiet_render_prints_nothing_on_success()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", "--size", "16x16", "-o", "q.png", "-q");
    Assert.Equal(0, run.ExitCode);
    Assert.Equal("", run.Error);
    Assert.Equal("", run.Out);
    Assert.True(File.Exists(dir.File("q.png")));
  }

  [Fact]
  public void Quiet_part_render_prints_nothing_on_success()
  {
    using var dir = new TempDirectory();
    CliRun part = CliRun.Of(dir.Path, "render", "--size", "16x16", "--tiles", "0/1", "-o", "p.grcis-part", "-q");
    Assert.Equal(0, part.ExitCode);
    Assert.Equal(("", ""), (part.Out, part.Error));
    Assert.True(File.Exists(dir.File("p.grcis-part")));
  }

  [Theory]
  [InlineData("a/b/x.png")]
  [InlineData("parts/x.grcis-part")]
  [InlineData("lin/x.pfm")]
  public void Missing_folders_of_the_output_are_created_as_animate_creates_its_frames_folder(string output)
  {
    using var dir = new TempDirectory();
    string[] tiles = output.EndsWith(".grcis-part", System.StringComparison.Ordinal) ? ["--tiles", "1/2"] : [];
    CliRun run = CliRun.Of(dir.Path, ["render", "--size", "40x30", "-o", output, .. tiles]);
    Assert.True(run.ExitCode == 0, run.Error);
    Assert.Equal(new[] { dir.File(output) }, dir.AllFiles());
    Assert.StartsWith("wrote " + dir.File(output) + ":", run.Out);
  }

  [Fact]
  public void A_file_where_an_output_folder_should_be_fails_before_rendering()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("a"), "x");
    CliRun run = CliRun.Of(dir.Path, "render", "--size", "40x30", "-o", "a/b/x.png");
    Assert.Equal(ExitCodes.Failure, run.ExitCode);
    Assert.Equal($"grcis: error: cannot write '{dir.File("a/b/x.png")}': '{dir.File("a")}' is a file, not a directory", Assert.Single(run.ErrorLines));
    Assert.Equal(new[] { dir.File("a") }, dir.AllFiles());
  }

  [Fact]
  public void Without_output_the_file_is_the_scene_slug_in_the_working_directory()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", "--size", "20x10", "-q");

    Assert.Equal(0, run.ExitCode);
    Assert.Equal(new[] { dir.File("sphere-on-the-plane.png") }, dir.AllFiles());
  }

  [Fact]
  public void Named_scene_is_found_ignoring_case_and_spaces()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", "five BALLS", "--size", "20x10", "-q");

    Assert.Equal(0, run.ExitCode);
    Assert.True(File.Exists(dir.File("five-balls.png")));
  }

  [Fact]
  public void Pfm_extension_writes_a_linear_float_map()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", "--size", "8x6", "-o", "lin.pfm", "-q");

    Assert.Equal(0, run.ExitCode);
    byte[] bytes = File.ReadAllBytes(dir.File("lin.pfm"));
    Assert.StartsWith("PF\n8 6\n-1.0\n", System.Text.Encoding.ASCII.GetString(bytes, 0, 12));
    Assert.Equal(12 + 8 * 6 * 3 * 4, bytes.Length);
  }

  [Fact]
  public void Same_seed_gives_identical_png_bytes_on_1_and_3_threads()
  {
    using var dir = new TempDirectory();
    string[] common = { "render", "--size", "48x32", "--spp", "4", "--jitter", "1", "--seed", "7", "-q" };
    Assert.Equal(0, CliRun.Of(dir.Path, [.. common, "-t", "1", "-o", "a.png"]).ExitCode);
    Assert.Equal(0, CliRun.Of(dir.Path, [.. common, "-t", "3", "-o", "b.png"]).ExitCode);
    Assert.Equal(File.ReadAllBytes(dir.File("a.png")), File.ReadAllBytes(dir.File("b.png")));
  }

  [Theory]
  [InlineData("independent")]
  [InlineData("sobol")]
  public void Each_sampler_gives_its_own_path_traced_image_the_same_on_1_and_3_threads(string sampler)
  {
    using var dir = new TempDirectory();
    string[] common = { "render", "--algorithm", "path", "--size", "24x16", "--spp", "16", "--seed", "7", "-q" };
    Assert.Equal(0, CliRun.Of(dir.Path, [.. common, "--sampler", sampler, "-t", "1", "-o", "a.pfm"]).ExitCode);
    Assert.Equal(0, CliRun.Of(dir.Path, [.. common, "--sampler", sampler, "-t", "3", "-o", "b.pfm"]).ExitCode);
    Assert.Equal(0, CliRun.Of(dir.Path, [.. common, "-t", "3", "-o", "cmj.pfm"]).ExitCode);
    Assert.Equal(File.ReadAllBytes(dir.File("a.pfm")), File.ReadAllBytes(dir.File("b.pfm")));
    Assert.NotEqual(File.ReadAllBytes(dir.File("a.pfm")), File.ReadAllBytes(dir.File("cmj.pfm")));
  }

  [Fact]
  public void Unknown_sampler_is_a_usage_error_naming_the_choices()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", "--sampler", "halton", "-o", "a.png");
    Assert.Equal(2, run.ExitCode);
    Assert.Contains("sobol", run.Error);
    Assert.False(File.Exists(dir.File("a.png")));
  }

  [Fact]
  public void Switching_off_shadows_changes_the_image()
  {
    using var dir = new TempDirectory();
    Assert.Equal(0, CliRun.Of(dir.Path, "render", "--size", "64x48", "-q", "-o", "a.png").ExitCode);
    Assert.Equal(0, CliRun.Of(dir.Path, "render", "--size", "64x48", "-q", "-o", "b.png", "--no-shadows").ExitCode);
    Assert.NotEqual(File.ReadAllBytes(dir.File("a.png")), File.ReadAllBytes(dir.File("b.png")));
  }

  [Fact]
  public void Cancelled_render_exits_130_and_writes_nothing()
  {
    using var dir = new TempDirectory();
    using var cts = new CancellationTokenSource();
    cts.Cancel();
    CliRun run = CliRun.Of(dir.Path, cts.Token, "render", "--size", "64x48", "-o", "c.png", "-q");

    Assert.Equal(ExitCodes.Cancelled, run.ExitCode);
    Assert.Contains("cancelled", Assert.Single(run.ErrorLines));
    Assert.Empty(dir.AllFiles());
  }

  [Fact]
  public void Existing_output_is_replaced_whole()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("o.png"), "old");
    Assert.Equal(0, CliRun.Of(dir.Path, "render", "--size", "10x10", "-o", "o.png", "-q").ExitCode);
    Assert.Equal(10, PngFile.Load(dir.File("o.png")).Width);
    Assert.Single(dir.AllFiles());
  }

  [Fact]
  public void List_prints_every_built_in_scene_one_per_line()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "list");

    Assert.Equal(0, run.ExitCode);
    string[] lines = run.Out.Split('\n', System.StringSplitOptions.RemoveEmptyEntries | System.StringSplitOptions.TrimEntries);
    Assert.Equal(Scenes.Names, lines);
    Assert.Contains(Scenes.DefaultSceneName, lines);
  }

  [Fact]
  public void Help_exits_zero_and_lists_the_render_options()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", "--help");
    Assert.Equal(0, run.ExitCode);
    foreach (string option in new[] { "--output", "--size", "--spp", "--jitter", "--threads", "--seed", "--sampler", "--gamma", "--no-shadows", "--no-reflections", "--no-refractions" })
      Assert.Contains(option, run.Out);
  }
}
