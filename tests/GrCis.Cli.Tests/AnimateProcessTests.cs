using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Threading;
using GrCis.TestSupport;

namespace GrCis.Cli.Tests;

/// <summary>One uninterrupted run of the animation the process tests compare against (rendered once per test class).</summary>
public sealed class OrbitBaseline : IDisposable
{
  /// <summary>scripts/Orbit.cs, 49 frames of 96x72 with 4 samples per pixel: a few seconds, long enough to interrupt.</summary>
  public static readonly string[] Args =
    { "animate", RepoPaths.Script("Orbit.cs"), "--size", "96x72", "--spp", "4", "--seed", "11" };

  readonly TempDirectory dir = new();

  public OrbitBaseline()
  {
    var (code, _, error) = GrcisProcess.Run(dir.Path, [.. Args, "-o", "frames/o###.png", "-q"]);
    Assert.True(code == 0, error);
    Frames = AnimateRun.Snapshot(dir.File("frames"));
    Assert.Equal(49, Frames.Length);
  }

  public (string Name, byte[] Bytes)[] Frames { get; }

  public void Dispose() => dir.Dispose();
}

/// <summary>
/// <c>grcis animate</c> as real processes: killed with SIGKILL and resumed, split into shards run
/// at once, run by GNU parallel, and asked for a video without ffmpeg. Each result must be the
/// baseline's frames byte for byte.
/// </summary>
public class AnimateProcessTests : IClassFixture<OrbitBaseline>
{
  readonly OrbitBaseline baseline;

  public AnimateProcessTests(OrbitBaseline baseline) => this.baseline = baseline;

  [Fact]
  public void Killed_run_resumed_gives_exactly_the_frames_of_an_uninterrupted_run()
  {
    using var dir = new TempDirectory();
    string frames = dir.File("frames");

    // One thread, frames in order: SIGKILL lands while later frames are still to come.
    using (Process p = GrcisProcess.Start(dir.Path, null, [.. OrbitBaseline.Args, "-o", "frames/o###.png", "--threads", "1", "-q"]))
    {
      var clock = Stopwatch.StartNew();
      while (CompleteFrames(frames) < 3 && !p.HasExited && clock.Elapsed < TimeSpan.FromMinutes(2))
        Thread.Sleep(5);
      Assert.False(p.HasExited, "the run finished before it could be killed; the test needs a longer animation");
      p.Kill();   // SIGKILL on Unix: no handler runs, nothing is cleaned up
      p.WaitForExit();
    }
    int before = CompleteFrames(frames);
    Assert.InRange(before, 3, 48);

    // Resume on two threads in the other parallel mode: the remaining frames, same bytes.
    var (code, stdout, error) = GrcisProcess.Run(dir.Path, [.. OrbitBaseline.Args, "-o", "frames/o###.png", "--resume", "--parallel", "frames"]);
    Assert.True(code == 0, error);
    Assert.Contains("complete, skipped", stdout);
    AnimateRun.AssertSameFiles(baseline.Frames, AnimateRun.Snapshot(frames));
  }

  [Fact]
  public void Three_shard_processes_together_equal_one_process()
  {
    using var dir = new TempDirectory();
    var procs = Enumerable.Range(0, 3)
      .Select(i => GrcisProcess.Start(dir.Path, null, [.. OrbitBaseline.Args, "-o", "frames/o###.png", "--shard", $"{i}/3"]))
      .ToList();
    for (int i = 0; i < 3; i++)
    {
      var (code, stdout, error) = GrcisProcess.Finish(procs[i]);
      procs[i].Dispose();
      Assert.True(code == 0, error);
      Assert.Contains($"wrote {(i == 0 ? 17 : 16)} frames", stdout);
    }
    AnimateRun.AssertSameFiles(baseline.Frames, AnimateRun.Snapshot(dir.File("frames")));
  }

  [SkippableFact]
  public void Gnu_parallel_runs_the_shards_and_the_frames_equal_one_process()
  {
    string parallel = RequiredTool.Find("parallel", "parallel");

    using var dir = new TempDirectory();
    // The recipe of docs/scale-out.md: one job per shard index, {} is the index; -q: nothing printed on success.
    var (code, stdout, error) = GrcisProcess.RunParallel(parallel, dir.Path, 3, [.. OrbitBaseline.Args, "-o", "frames/o###.png", "-q", "--shard", "{}/3"]);
    Assert.True(code == 0, $"parallel exited {code}: {error}");
    Assert.Equal("", stdout);
    Assert.Equal("", error);
    AnimateRun.AssertSameFiles(baseline.Frames, AnimateRun.Snapshot(dir.File("frames")));
  }

  [Fact]
  public void Missing_ffmpeg_is_one_clear_line_the_frames_are_kept_and_the_exit_code_is_1()
  {
    using var dir = new TempDirectory();
    var env = new Dictionary<string, string> { ["GRCIS_FFMPEG"] = dir.File("no-such-ffmpeg") };
    var (code, stdout, error) = GrcisProcess.Run(dir.Path, env,
      "animate", "Two spheres", "--to", "0.2", "--fps", "10", "--size", "16x12", "-o", "f/t##.png", "--video", "t.mp4", "-q");

    Assert.Equal(1, code);
    Assert.Equal("", stdout);   // -q: the error alone says what happened
    string line = Assert.Single(error.Split('\n', StringSplitOptions.RemoveEmptyEntries));
    Assert.Equal($"grcis: error: --video needs ffmpeg, but GRCIS_FFMPEG='{dir.File("no-such-ffmpeg")}' is not an executable file; the frames are kept in '{dir.File("f")}'", line);
    Assert.Equal(3, Directory.GetFiles(dir.File("f")).Length);
    Assert.False(File.Exists(dir.File("t.mp4")));
  }

  [SkippableFact]
  public void Video_is_encoded_with_ffmpeg_at_the_animation_frame_rate()
  {
    // A machine without ffmpeg still runs the missing-ffmpeg test above.
    RequiredTool.Find("ffmpeg", "ffmpeg");
    using var dir = new TempDirectory();
    var (code, stdout, error) = GrcisProcess.Run(dir.Path,
      "animate", "Two spheres", "--to", "1", "--fps", "10", "--size", "33x25", "-o", "f/t##.png", "--video", "t.mp4");
    Assert.True(code == 0, error);
    Assert.Contains("wrote " + dir.File("t.mp4") + ": frames 0-10 at 10 fps", stdout);
    byte[] head = File.ReadAllBytes(dir.File("t.mp4"))[..12];
    Assert.Equal("ftyp", System.Text.Encoding.ASCII.GetString(head, 4, 4));
    Assert.Empty(Directory.GetFiles(dir.Path, ".t.tmp-*"));

    // ffprobe (from the same package) confirms the frame count and rate.
    string? ffprobe = RequiredTool.OnPath("ffprobe", Environment.GetEnvironmentVariable("PATH"));
    if (ffprobe != null)
    {
      var psi = new ProcessStartInfo(ffprobe) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
      foreach (string a in new[] { "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries", "stream=nb_read_frames,r_frame_rate,width,height", "-of", "csv=p=0", dir.File("t.mp4") })
        psi.ArgumentList.Add(a);
      using Process p = Process.Start(psi)!;
      string info = p.StandardOutput.ReadToEnd().Trim();
      p.WaitForExit();
      Assert.Equal("34,26,10/1,11", info);
    }
  }

  static int CompleteFrames(string dir) =>
    Directory.Exists(dir) ? Directory.GetFiles(dir, "*.png").Length : 0;
}
