using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using System.Threading;
using GrCis.TestSupport;

namespace GrCis.Cli.Tests;

/// <summary>
/// The Slurm recipes of docs/scale-out.md, taken from the page as they are and run on a one-node Slurm
/// (<see cref="SlurmCluster"/>), small: only the variables the page names (N, SIZE, FRAMES) are set. Array
/// tasks are cancelled, killed with SIGKILL and requeued while rendering, and a stale temporary file lies in
/// the frames folder; the final job (afterany) still runs, and the frames, the video and the merged image
/// are the bytes one process writes.
/// </summary>
public class SlurmRecipeTests : IClassFixture<SlurmCluster>
{
  static readonly TimeSpan Limit = TimeSpan.FromMinutes(8);
  readonly SlurmCluster cluster;

  public SlurmRecipeTests(SlurmCluster cluster) => this.cluster = cluster;

  /// <summary>The <c>```sh</c> blocks of one section of the page: files by name (the line before says <c>`x.sbatch`</c>), and the submit block.</summary>
  internal static (Dictionary<string, string> Files, string Submit) Recipe(string markdown, string heading)
  {
    string[] all = markdown.Split('\n');
    int start = Array.IndexOf(all, heading);
    Assert.True(start >= 0, $"docs/scale-out.md has no section '{heading}'");
    var files = new Dictionary<string, string>();
    string? submit = null;
    string before = "";
    for (int i = start + 1; i < all.Length; i++)
    {
      if (all[i].StartsWith('#'))
        break;   // the next heading (lines in code blocks are skipped below)
      if (all[i].Trim() != "```sh")
      {
        // The first line of the paragraph before a block names its file.
        if (all[i].Trim().Length > 0 && all[i - 1].Trim().Length == 0)
          before = all[i];
        continue;
      }
      int close = Array.FindIndex(all, i + 1, l => l.StartsWith("```", StringComparison.Ordinal));
      Assert.True(close > i, $"unclosed code block after '{before}'");
      string text = string.Join('\n', all[(i + 1)..close]) + "\n";
      Match name = Regex.Match(before, @"^`([\w.-]+\.sbatch)`");
      if (name.Success)
        files[name.Groups[1].Value] = text;
      else if (text.Contains("sbatch --parsable", StringComparison.Ordinal))
        submit = text;
      before = "";
      i = close;
    }
    Assert.True(submit != null, $"no submit block (sbatch --parsable) in '{heading}'");
    return (files, submit!);
  }

  static (Dictionary<string, string> Files, string Submit) DocRecipe(string heading) =>
    Recipe(File.ReadAllText(Path.Combine(RepoPaths.Root, "docs", "scale-out.md")), heading);

  /// <summary>A project root as the page assumes: <c>scripts/</c>, the recipe's files, and <c>grcis</c> on PATH.</summary>
  internal static Dictionary<string, string?> ProjectRoot(TempDirectory dir, Dictionary<string, string> files, string? conf, params (string, string)[] variables)
  {
    File.CreateSymbolicLink(dir.File("scripts"), RepoPaths.Scripts);
    foreach (var (name, text) in files)
      File.WriteAllText(dir.File(name), text);
    // The built grcis, as the published one on the nodes' PATH.
    string bin = Directory.CreateDirectory(dir.File("bin")).FullName;
    File.WriteAllText(Path.Combine(bin, "grcis"), $"#!/bin/sh\nexec '{GrcisProcess.Dotnet}' exec '{GrcisProcess.Dll}' \"$@\"\n");
    File.SetUnixFileMode(Path.Combine(bin, "grcis"), (UnixFileMode)0b111_101_101);
    var env = new Dictionary<string, string?>
    {
      ["SLURM_CONF"] = conf,   // null: not set
      ["PATH"] = bin + ":" + Environment.GetEnvironmentVariable("PATH"),
    };
    foreach (var (k, v) in variables)
      env[k] = v;
    return env;
  }

  /// <summary>Runs the submit block with bash (as pasted) and returns the array job's id.</summary>
  string Submit(TempDirectory dir, Dictionary<string, string?> env, string submit, string jobName)
  {
    File.WriteAllText(dir.File("submit.sh"), submit);
    var (code, output) = Shell.Run(dir.Path, env, TimeSpan.FromMinutes(1), "bash", "--noprofile", "--norc", "-e", "-o", "pipefail", "submit.sh");
    Assert.True(code == 0, $"the submit block failed (exit {code}):\n{submit}\n{output}");
    var (_, ids) = cluster.Command("squeue", "-h", "--name=" + jobName, "-o", "%F");
    string? id = ids.Split('\n', StringSplitOptions.RemoveEmptyEntries).FirstOrDefault();
    Assert.True(id != null, $"no job '{jobName}' in the queue after:\n{output}");
    return id!.Trim();
  }

  /// <summary>Waits until <paramref name="ready"/> holds (polling), failing with <paramref name="what"/> after the limit.</summary>
  static void WaitFor(Func<bool> ready, string what)
  {
    var clock = Stopwatch.StartNew();
    while (!ready())
    {
      Assert.True(clock.Elapsed < Limit, $"waited {Limit.TotalMinutes} minutes for {what}");
      Thread.Sleep(100);
    }
  }

  static string Log(TempDirectory dir, string name) => File.Exists(dir.File(name)) ? File.ReadAllText(dir.File(name)) : "";

  [SkippableFact]
  public void Animation_recipe_with_a_cancelled_and_a_killed_task_gives_the_frames_and_video_of_one_process()
  {
    string conf = cluster.Start();
    RequiredTool.Find("ffmpeg", "ffmpeg");
    var (files, submit) = DocRecipe("## Slurm job arrays");
    Assert.Equal(new[] { "encode.sbatch", "render.sbatch" }, files.Keys.Order());
    Assert.Contains("afterany", submit);

    using var dir = new TempDirectory();
    var env = ProjectRoot(dir, files, conf, ("N", "4"), ("SIZE", "160x120"), ("FRAMES", "0-7"));
    // A temporary file a killed run left on the shared folder (a frame being written when its node died).
    Directory.CreateDirectory(dir.File("frames"));
    File.WriteAllBytes(dir.File("frames/out0003.png.tmp-0123456789ab"), [1, 2, 3]);
    string job = Submit(dir, env, submit, "orbit");

    // Task k renders frames k and k + 4; tasks 1, 2 and 3 are cut after their first frame is saved:
    // cancelled, killed (SIGKILL, no handler runs), requeued (it starts again and resumes).
    WaitFor(() => Log(dir, $"logs/orbit-{job}_1.log").Contains(" saved, ", StringComparison.Ordinal), "task 1's first frame");
    Assert.Equal(0, cluster.Command("scancel", $"{job}_1").Code);
    WaitFor(() => Log(dir, $"logs/orbit-{job}_2.log").Contains(" saved, ", StringComparison.Ordinal), "task 2's first frame");
    Assert.Equal(0, cluster.Command("scancel", "--full", "--signal=KILL", $"{job}_2").Code);
    WaitFor(() => Log(dir, $"logs/orbit-{job}_3.log").Contains(" saved, ", StringComparison.Ordinal), "task 3's first frame");
    var requeue = cluster.Command("scontrol", "requeue", $"{job}_3");
    Assert.True(requeue.Code == 0, requeue.Output);
    cluster.WaitUntilIdle(Limit);

    Assert.Equal("CANCELLED", cluster.State($"{job}_1"));
    Assert.NotEqual("COMPLETED", cluster.State($"{job}_2"));   // killed: FAILED
    Assert.Equal("COMPLETED", cluster.State($"{job}_0"));
    Assert.Equal("COMPLETED", cluster.State($"{job}_3"));
    // The requeued task's second run (its log starts again) skipped what the first run saved: its first frame, or both
    // when the requeue landed after the second one was saved too (a 160x120 frame can take less than the poll).
    string requeued = Log(dir, $"logs/orbit-{job}_3.log");
    Assert.True(Regex.IsMatch(requeued, @"2 frames \([12] already complete, skipped\)"), requeued);

    // A task's log: progress lines, then its summary last (stdout and stderr in the order written).
    string[] log0 = Log(dir, $"logs/orbit-{job}_0.log").Split('\n', StringSplitOptions.RemoveEmptyEntries);
    Assert.Equal(2, log0.Count(l => l.Contains(" saved, ", StringComparison.Ordinal)));
    Assert.StartsWith("wrote 2 frames to ", log0[^1]);

    // The video job rendered what the two tasks left missing, then encoded: the frames the cut tasks did not save (one
    // or two each; a cut may land after a second frame is saved when a frame takes less than the poll), the rest skipped.
    string video = Directory.GetFiles(dir.File("logs"), "orbit-video-*.log").Select(File.ReadAllText).Single();
    Match wrote = Regex.Match(video, @"wrote ([1-4]) frames? \(([4-7]) complete, skipped\)");
    Assert.True(wrote.Success, video);
    Assert.Equal(8, int.Parse(wrote.Groups[1].Value) + int.Parse(wrote.Groups[2].Value));
    Assert.DoesNotContain("tmp-", string.Join(' ', Directory.GetFiles(dir.File("frames"))));
    Assert.Contains("wrote " + dir.File("orbit.mp4") + ": frames 0-7 at 12 fps", video);

    // One process, the same options.
    var (code, _, error) = GrcisProcess.Run(dir.Path, "animate", "scripts/Orbit.cs", "-o", "one/out####.png", "--size", "160x120",
      "--spp", "16", "--seed", "1", "--frames", "0-7", "--video", "one.mp4", "-q");
    Assert.True(code == 0, error);
    AnimateRun.AssertSameFiles(AnimateRun.Snapshot(dir.File("one")), AnimateRun.Snapshot(dir.File("frames")));
    Assert.Equal(File.ReadAllBytes(dir.File("one.mp4")), File.ReadAllBytes(dir.File("orbit.mp4")));
  }

  [SkippableFact]
  public void Still_recipe_with_a_cancelled_task_merges_the_image_of_one_process()
  {
    string conf = cluster.Start();
    var (files, submit) = DocRecipe("### Slurm job array");
    Assert.Equal(new[] { "merge.sbatch", "still.sbatch" }, files.Keys.Order());
    Assert.Contains("mkdir -p logs parts", submit);

    using var dir = new TempDirectory();
    var env = ProjectRoot(dir, files, conf, ("N", "4"), ("SIZE", "160x120"));
    string job = Submit(dir, env, submit, "balls");

    // Task 1 is cancelled while it runs (its part is written only when complete, so it is missing).
    WaitFor(() => cluster.State($"{job}_1") == "RUNNING", "task 1 to start");
    Assert.Equal(0, cluster.Command("scancel", $"{job}_1").Code);
    cluster.WaitUntilIdle(Limit);
    Assert.Equal("CANCELLED", cluster.State($"{job}_1"));

    string merge = Directory.GetFiles(dir.File("logs"), "balls-merge-*.log").Select(File.ReadAllText).Single();
    Assert.Contains("wrote " + dir.File("balls.png") + ": 160x120 from 4 parts", merge);
    var (code, _, error) = GrcisProcess.Run(dir.Path, "render", "scripts/FiveBalls.cs", "--size", "160x120", "--spp", "64", "--seed", "1", "-o", "one.png", "-q");
    Assert.True(code == 0, error);
    Assert.Equal(File.ReadAllBytes(dir.File("one.png")), File.ReadAllBytes(dir.File("balls.png")));
  }

  [Fact]
  public void Recipe_blocks_are_found_by_the_file_name_line_before_them()
  {
    const string page = "## A\n\n`a.sbatch`:\n\n```sh\necho a\n```\n\n`b.sbatch`, more words\nover two lines:\n\n```sh\necho b\n```\n\n```sh\njid=$(sbatch --parsable a.sbatch)\n```\n## B\n```sh\nsbatch --parsable x\n```\n";
    var (files, submit) = Recipe(page, "## A");
    Assert.Equal("echo a\n", files["a.sbatch"]);
    Assert.Equal("echo b\n", files["b.sbatch"]);
    Assert.Equal("jid=$(sbatch --parsable a.sbatch)\n", submit);
  }
}
