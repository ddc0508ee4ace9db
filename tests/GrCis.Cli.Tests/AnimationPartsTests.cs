using System.IO;
using System.Linq;
using GrCis.Cli.Animation;
using GrCis.Cli.Jobs;
using GrCis.Hosting;

namespace GrCis.Cli.Tests;

public class AnimationPartsTests
{
  static readonly string Root = Path.GetTempPath();

  [Theory]
  [InlineData("frames/out####.png", 7, "frames/out0007.png")]
  [InlineData("frames/out####.png", 12345, "frames/out12345.png")]
  [InlineData("a#b##.png", 3, "a#b03.png")]
  [InlineData("clip.png", 42, "clip0042.png")]
  [InlineData("f#.PNG", 9, "f9.PNG")]
  public void Frame_pattern_fills_the_last_hash_run_of_the_file_name(string pattern, int frame, string expected)
  {
    FramePattern p = FramePattern.Parse(pattern, Root);
    Assert.Equal(Path.GetFullPath(expected, Root), p.FileOf(frame));
  }

  [Fact]
  public void Frame_pattern_in_ffmpeg_syntax_escapes_percent()
  {
    FramePattern p = FramePattern.Parse("100%/f_##.png", Root);
    Assert.Equal(Path.Combine(Path.GetFullPath("100%", Root), "f_%02d.png"), p.FfmpegPattern());
    Assert.Equal(Path.Combine(Root, "a%%b%04d.png"), FramePattern.Parse("a%b.png", Root).FfmpegPattern());
  }

  [Fact]
  public void Shard_includes_frames_congruent_to_its_index()
  {
    ShardSpec s = ShardSpec.Parse("2/3");
    Assert.Equal(new[] { 2, 5, 8 }, Enumerable.Range(0, 10).Where(s.Includes));
    Assert.Equal(ShardSpec.All, ShardSpec.Parse("0/1"));
    Assert.Throws<UsageException>(() => ShardSpec.Parse("-1/3"));
    Assert.Throws<UsageException>(() => ShardSpec.Parse("1/0"));
  }

  [Fact]
  public void Frame_range_parses_a_single_frame_and_a_span()
  {
    Assert.Equal(new FrameRange(4, 4), FrameRange.Parse("4"));
    Assert.Equal(new FrameRange(0, 249), FrameRange.Parse(" 0-249 "));
    Assert.Throws<UsageException>(() => FrameRange.Parse("a-b"));
  }

  [Theory]
  [InlineData(ParallelMode.Auto, 160, 120, 2, 10, ParallelMode.Frames)]
  [InlineData(ParallelMode.Auto, 640, 480, 2, 10, ParallelMode.Frames)]
  [InlineData(ParallelMode.Auto, 641, 480, 2, 10, ParallelMode.Tiles)]
  [InlineData(ParallelMode.Auto, 1920, 1080, 8, 100, ParallelMode.Tiles)]
  [InlineData(ParallelMode.Auto, 160, 120, 1, 10, ParallelMode.Tiles)]
  [InlineData(ParallelMode.Auto, 160, 120, 2, 1, ParallelMode.Tiles)]
  [InlineData(ParallelMode.Frames, 640, 480, 2, 10, ParallelMode.Frames)]
  [InlineData(ParallelMode.Tiles, 16, 16, 2, 10, ParallelMode.Tiles)]
  public void Auto_parallelism_chooses_frames_for_small_frames(ParallelMode asked, int w, int h, int threads, int frames, ParallelMode chosen) =>
    Assert.Equal(chosen, FrameScheduler.Choose(asked, new ImageSize(w, h), threads, frames));

  [Theory]
  [InlineData(ParallelMode.Frames, 3, 7)]
  [InlineData(ParallelMode.Frames, 2, 1)]
  [InlineData(ParallelMode.Tiles, 2, 5)]
  public void Scheduler_saves_every_frame_once_in_either_mode(ParallelMode mode, int threads, int count)
  {
    using var dir = new TempDirectory();
    var size = new ImageSize(6, 4);
    var timeline = new Rendering.AnimationTimeline(0, 10, 1);
    var store = new FrameStore(FramePattern.Parse("f##.png", dir.Path), size, 1.0, new FrameFingerprint("clock", "test", size, 1, 0, timeline, 0));
    store.Prepare();
    RenderPlan settings = Precedence.Resolve(new RenderSettings { Width = size.Width, Height = size.Height }, GivenSettings.None, null);
    var renderer = new FrameRenderer(TestAnimations.Clock(), settings, timeline);
    var saved = new System.Collections.Generic.List<int>();
    int n = new FrameScheduler(renderer, store).Run(Enumerable.Range(2, count).ToList(), mode, threads, saved.Add, default);

    Assert.Equal(count, n);
    Assert.Equal(Enumerable.Range(2, count), saved.Order());
    Assert.All(Enumerable.Range(2, count), k => Assert.True(store.IsComplete(k)));
  }
}
