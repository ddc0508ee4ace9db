using System;
using System.IO;
using System.Linq;
using System.Threading;
using Rendering.Imaging;

namespace GrCis.Cli.Tests;

public class AnimateCommandTests
{
  static string[] Names(TempDirectory dir, string sub) =>
    Directory.GetFiles(Path.Combine(dir.Path, sub)).Select(Path.GetFileName).Order(StringComparer.Ordinal).ToArray()!;

  static int Red(string file) => PngFile.Load(file).GetPixel(2, 2).R;

  [Fact]
  public void Frames_cover_start_to_end_inclusive_and_hashes_set_the_width()
  {
    using var dir = new TempDirectory();
    CliRun run = AnimateRun.Of(dir.Path, "animate", "test-clock", "-o", "f/out###.png", "--from", "1", "--to", "3", "--fps", "2",
      "--size", "8x6", "--gamma", "1");

    Assert.True(run.ExitCode == 0, run.Error);
    Assert.Equal(new[] { "out000.png", "out001.png", "out002.png", "out003.png", "out004.png" }, Names(dir, "f"));
    // Frame k is at 1 + k/2 s; red = time / 10, quantized by truncation.
    int[] red = Enumerable.Range(0, 5).Select(k => Red(dir.File($"f/out{k:D3}.png"))).ToArray();
    int[] expected = Enumerable.Range(0, 5).Select(k => (int)((1.0 + k / 2.0) / 10.0 * 255.0)).ToArray();
    for (int k = 0; k < 5; k++)
      Assert.InRange(red[k], expected[k] - 1, expected[k] + 1);
    Assert.Contains("wrote 5 frames", run.Out);
  }

  [Fact]
  public void Pattern_without_hashes_gets_four_digits_before_the_extension()
  {
    using var dir = new TempDirectory();
    CliRun run = AnimateRun.Of(dir.Path, "animate", "test-clock", "-o", "f/clip.png", "--to", "0.5", "--fps", "2", "--size", "4x4");
    Assert.True(run.ExitCode == 0, run.Error);
    Assert.Equal(new[] { "clip0000.png", "clip0001.png" }, Names(dir, "f"));
  }

  [Fact]
  public void Range_comes_from_the_command_line_then_the_script_then_the_scene()
  {
    using var dir = new TempDirectory();
    // The "script" asks for 2..3 s at 4 fps: 5 frames.
    CliRun script = AnimateRun.Of(dir.Path, "animate", "test-clock-script", "-o", "a/f##.png", "--size", "4x4", "--gamma", "1");
    Assert.True(script.ExitCode == 0, script.Error);
    Assert.Equal(5, Names(dir, "a").Length);
    Assert.InRange(Red(dir.File("a/f00.png")), 50, 51);   // 2 s → 0.2 · 255

    // The command line wins over the script's fps.
    CliRun cli = AnimateRun.Of(dir.Path, "animate", "test-clock-script", "-o", "b/f##.png", "--size", "4x4", "--fps", "1");
    Assert.True(cli.ExitCode == 0, cli.Error);
    Assert.Equal(2, Names(dir, "b").Length);

    // Without a script range the scene's own Start/End (0..10 s) with --fps 0.5: 6 frames.
    CliRun scene = AnimateRun.Of(dir.Path, "animate", "test-clock", "-o", "c/f##.png", "--size", "4x4", "--fps", "0.5");
    Assert.True(scene.ExitCode == 0, scene.Error);
    Assert.Equal(6, Names(dir, "c").Length);
  }

  [Fact]
  public void Frames_in_parallel_and_tiles_in_parallel_write_the_same_bytes()
  {
    using var dir = new TempDirectory();
    string[] common = { "animate", "test-moving", "--fps", "2", "--size", "40x30", "--spp", "4", "--threads", "2" };
    CliRun frames = AnimateRun.Of(dir.Path, [.. common, "-o", "frames/f##.png", "--parallel", "frames"]);
    CliRun tiles = AnimateRun.Of(dir.Path, [.. common, "-o", "tiles/f##.png", "--parallel", "tiles"]);
    CliRun one = AnimateRun.Of(dir.Path, [.. common[..^2], "--threads", "1", "-o", "one/f##.png"]);

    Assert.True(frames.ExitCode == 0, frames.Error);
    Assert.Contains("parallel frames on 2 threads", frames.Out);
    Assert.Contains("parallel tiles on 2 threads", tiles.Out);
    var expected = AnimateRun.Snapshot(dir.File("frames"));
    Assert.Equal(9, expected.Length);
    AnimateRun.AssertSameFiles(expected, AnimateRun.Snapshot(dir.File("tiles")));
    AnimateRun.AssertSameFiles(expected, AnimateRun.Snapshot(dir.File("one")));
  }

  [Fact]
  public void Quiet_animation_prints_nothing_on_success_and_one_thread_is_singular()
  {
    using var dir = new TempDirectory();
    string[] args = { "animate", "test-moving", "--fps", "1", "--size", "16x12", "--threads", "1" };
    CliRun quiet = AnimateRun.Of(dir.Path, [.. args, "-o", "q/f#.png", "-q"]);
    Assert.True(quiet.ExitCode == 0, quiet.Error);
    Assert.Equal(("", ""), (quiet.Out, quiet.Error));
    Assert.Equal(5, Directory.GetFiles(dir.File("q")).Length);

    CliRun loud = AnimateRun.Of(dir.Path, [.. args, "-o", "l/f#.png"]);
    string summary = Assert.Single(loud.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries));
    Assert.StartsWith("wrote 5 frames to ", summary);
    Assert.EndsWith(" on 1 thread", summary);
  }

  [Fact]
  public void Static_frames_of_a_built_in_scene_differ_only_by_their_frame_seed()
  {
    using var dir = new TempDirectory();
    CliRun run = AnimateRun.Of(dir.Path, "animate", "Two spheres", "-o", "f/s#.png", "--to", "1", "--fps", "1",
      "--size", "24x18", "--spp", "4");
    Assert.True(run.ExitCode == 0, run.Error);
    byte[] a = PngFile.Load(dir.File("f/s0.png")).Data, b = PngFile.Load(dir.File("f/s1.png")).Data;
    Assert.False(a.AsSpan().SequenceEqual(b), "jittered samples are seeded per frame");
    int close = a.Zip(b).Count(p => Math.Abs(p.First - p.Second) <= 40);
    Assert.True(close > a.Length * 9 / 10, "the scene itself does not move");
  }

  [Fact]
  public void Shards_together_write_exactly_the_frames_of_one_run()
  {
    using var dir = new TempDirectory();
    string[] common = { "animate", "test-moving", "--fps", "2", "--size", "20x16", "--spp", "4" };
    Assert.Equal(0, AnimateRun.Of(dir.Path, [.. common, "-o", "all/f##.png"]).ExitCode);
    for (int i = 0; i < 3; i++)
    {
      CliRun shard = AnimateRun.Of(dir.Path, [.. common, "-o", "sh/f##.png", "--shard", $"{i}/3"]);
      Assert.True(shard.ExitCode == 0, shard.Error);
      Assert.Contains($"shard {i}/3", shard.Out);
    }
    Assert.Equal(new[] { "f01.png", "f04.png", "f07.png" },
      AnimateRun.Snapshot(dir.File("sh")).Select(f => f.Name).Where(n => new[] { 1, 4, 7 }.Any(k => n == $"f{k:D2}.png")));
    AnimateRun.AssertSameFiles(AnimateRun.Snapshot(dir.File("all")), AnimateRun.Snapshot(dir.File("sh")));
  }

  [Fact]
  public void Resume_skips_complete_frames_redoes_broken_ones_and_removes_stale_temporaries()
  {
    using var dir = new TempDirectory();
    string[] args = { "animate", "test-moving", "--fps", "1", "--size", "20x16", "-o", "f/m#.png" };
    Assert.Equal(0, AnimateRun.Of(dir.Path, args).ExitCode);
    var first = AnimateRun.Snapshot(dir.File("f"));
    Assert.Equal(5, first.Length);

    // A truncated frame, a missing frame and a temporary file a killed run left behind.
    File.WriteAllBytes(dir.File("f/m1.png"), first[1].Bytes[..40]);
    File.Delete(dir.File("f/m3.png"));
    File.WriteAllBytes(dir.File("f/m3.png.tmp-0123456789ab"), new byte[] { 1, 2, 3 });
    DateTime untouched = File.GetLastWriteTimeUtc(dir.File("f/m0.png"));

    CliRun resumed = AnimateRun.Of(dir.Path, [.. args, "--resume"]);
    Assert.True(resumed.ExitCode == 0, resumed.Error);
    Assert.Contains("wrote 2 frames (3 complete, skipped)", resumed.Out);
    Assert.Contains("3 already complete, skipped", resumed.Error);
    Assert.Equal(untouched, File.GetLastWriteTimeUtc(dir.File("f/m0.png")));
    AnimateRun.AssertSameFiles(first, AnimateRun.Snapshot(dir.File("f")));
  }

  [Fact]
  public void Resume_renders_again_a_frame_of_another_size()
  {
    using var dir = new TempDirectory();
    Assert.Equal(0, AnimateRun.Of(dir.Path, "animate", "test-clock", "--to", "0", "--size", "8x8", "-o", "f#.png").ExitCode);
    CliRun again = AnimateRun.Of(dir.Path, "animate", "test-clock", "--to", "0", "--size", "6x4", "-o", "f#.png", "--resume");
    Assert.True(again.ExitCode == 0, again.Error);
    Assert.Contains("wrote 1 frame to ", again.Out);
    Assert.Equal(6, PngFile.Load(dir.File("f0.png")).Width);
  }

  [Fact]
  public void Shutter_blurs_a_moving_object_deterministically()
  {
    using var dir = new TempDirectory();
    string[] common = { "animate", "test-moving", "--fps", "1", "--frames", "2", "--size", "64x32", "--spp", "16", "-q" };
    Assert.Equal(0, AnimateRun.Of(dir.Path, [.. common, "-o", "sharp/f#.png"]).ExitCode);
    Assert.Equal(0, AnimateRun.Of(dir.Path, [.. common, "-o", "blur/f#.png", "--shutter", "1"]).ExitCode);
    Assert.Equal(0, AnimateRun.Of(dir.Path, [.. common, "-o", "blur2/f#.png", "--shutter", "1", "--threads", "1"]).ExitCode);

    Rgb8Image sharp = PngFile.Load(dir.File("sharp/f2.png")), blur = PngFile.Load(dir.File("blur/f2.png"));
    // Pixels that are neither background (0) nor the sphere's flat ambient red: edges, smeared by motion.
    byte inside = sharp.Data.Where((v, i) => i % 3 == 0 && v > 0).GroupBy(v => v).OrderByDescending(g => g.Count()).First().Key;
    int Partial(Rgb8Image img) => Enumerable.Range(0, img.Width * img.Height)
      .Count(i => img.Data[3 * i] != 0 && Math.Abs(img.Data[3 * i] - inside) > 2);
    Assert.False(sharp.ContentEquals(blur));
    // The sphere moves about 1.5 diameters while the shutter is open: it covers more pixels, mostly partially.
    int Covered(Rgb8Image img) => Enumerable.Range(0, img.Width * img.Height).Count(i => img.Data[3 * i] != 0);
    Assert.True(Covered(blur) > Covered(sharp) * 3 / 2, $"blurred covers {Covered(blur)} vs sharp {Covered(sharp)} pixels");
    Assert.True(Partial(blur) > 2 * Partial(sharp), $"blurred {Partial(blur)} vs sharp {Partial(sharp)} partial pixels");
    AnimateRun.AssertSameFiles(AnimateRun.Snapshot(dir.File("blur")), AnimateRun.Snapshot(dir.File("blur2")));
  }

  [Fact]
  public void Progress_lines_show_frames_done_rate_and_time_left()
  {
    using var dir = new TempDirectory();
    CliRun run = AnimateRun.Of(dir.Path, "animate", "test-clock", "--to", "3", "--fps", "1", "--size", "8x8", "-o", "f#.png");
    Assert.True(run.ExitCode == 0, run.Error);
    string[] lines = run.ErrorLines.Where(l => l.Contains("saved")).ToArray();
    Assert.Equal(4, lines.Length);
    Assert.Matches(@"^animate test-clock: frame \d saved, 1/4 frames, \d+\.\d\d frames/s, \d+:\d\d:\d\d left$", lines[0]);
    Assert.EndsWith("4/4 frames, " + lines[^1].Split(", ")[^1], lines[^1]);
    Assert.DoesNotContain("left", lines[^1]);
    Assert.DoesNotContain('\u001b', run.Error);
  }

  [Fact]
  public void Cancel_stops_between_frames_and_keeps_finished_ones()
  {
    using var dir = new TempDirectory();
    using var cts = new CancellationTokenSource();
    cts.Cancel();
    CliRun run = AnimateRun.Of(dir.Path, cts.Token, "animate", "test-clock", "--size", "8x8", "-o", "f/x#.png");
    Assert.Equal(130, run.ExitCode);
    Assert.Contains("--resume", run.Error);
    Assert.Empty(dir.AllFiles());
  }

  [Theory]
  [InlineData("frames")]
  [InlineData("tiles")]
  public void A_scene_that_throws_fails_the_run_with_one_line_and_keeps_earlier_frames(string mode)
  {
    using var dir = new TempDirectory();
    CliRun run = AnimateRun.Of(dir.Path, "animate", "test-broken", "--to", "4", "--fps", "1", "--size", "8x8",
      "-o", "f/b#.png", "--parallel", mode, "--threads", "2", "-q");
    Assert.Equal(1, run.ExitCode);
    Assert.Equal("grcis: error: render failed: the background broke at t = 2", run.Error.Trim());
    Assert.Equal("", run.Out);
    string[] files = Directory.GetFiles(dir.File("f")).Select(Path.GetFileName).ToArray()!;
    Assert.Contains("b0.png", files);
    Assert.DoesNotContain("b2.png", files);
    Assert.DoesNotContain(files, f => f!.Contains(".tmp-"));
  }

  [Theory]
  [InlineData("--shard", "3/3", "invalid --shard '3/3': the index runs from 0 to 2")]
  [InlineData("--shard", "x", "invalid --shard 'x': expected INDEX/COUNT, e.g. 0/4 (index from 0)")]
  [InlineData("--frames", "5-2", "invalid --frames '5-2': the last frame comes before the first")]
  [InlineData("--frames", "0-300", "invalid --frames 0-300: the animation has frames 0-250 (0 s to 10 s at 25 fps)")]
  [InlineData("--parallel", "gpu", "invalid --parallel 'gpu': use auto, frames or tiles")]
  [InlineData("--shutter", "2", "invalid --shutter 2: must be between 0 (sharp) and 1 (a whole frame)")]
  [InlineData("--fps", "0", "invalid animation range --fps 0: Frames per second must be a positive number.")]
  public void Bad_arguments_are_one_line_usage_errors_and_write_nothing(string option, string value, string message)
  {
    using var dir = new TempDirectory();
    CliRun run = AnimateRun.Of(dir.Path, "animate", "test-clock", "-o", "f/x#.png", "--size", "4x4", option, value);
    Assert.Equal(2, run.ExitCode);
    Assert.Equal("grcis: error: " + message, run.Error.Trim());
    Assert.Empty(dir.AllFiles());
  }

  [Fact]
  public void Output_must_be_a_png_pattern()
  {
    using var dir = new TempDirectory();
    CliRun run = AnimateRun.Of(dir.Path, "animate", "test-clock", "-o", "f/x#.jpg");
    Assert.Equal(2, run.ExitCode);
    Assert.Contains("must end in .png", run.Error);
    CliRun none = AnimateRun.Of(dir.Path, "animate", "test-clock");
    Assert.Equal(2, none.ExitCode);
    Assert.Contains("missing -o", none.Error);
  }

  [Fact]
  public void Video_with_a_shard_is_refused_with_the_recipe()
  {
    using var dir = new TempDirectory();
    CliRun run = AnimateRun.Of(dir.Path, "animate", "test-clock", "-o", "f#.png", "--shard", "0/2", "--video", "v.mp4");
    Assert.Equal(2, run.ExitCode);
    Assert.Contains("--resume --video", run.Error);
  }

  [Fact]
  public void Video_into_a_missing_folder_fails_before_rendering()
  {
    using var dir = new TempDirectory();
    CliRun run = AnimateRun.Of(dir.Path, "animate", "test-clock", "-o", "f#.png", "--size", "4x4", "--video", "no/v.mp4");
    Assert.Equal(1, run.ExitCode);
    Assert.Equal($"grcis: error: cannot write video '{dir.File("no/v.mp4")}': directory '{dir.File("no")}' does not exist", run.Error.Trim());
    Assert.Empty(dir.AllFiles());
  }
}
