using System;
using System.IO;
using System.Linq;
using GrCis.TestSupport;

namespace GrCis.Cli.Tests;

/// <summary>
/// The one-machine GNU parallel recipe for animations in docs/scale-out.md, taken from the page as it is and
/// run with bash, small (only <c>SIZE</c>, which the block names, is set): the frames and the video are the
/// bytes one process writes.
/// </summary>
public class ParallelRecipeTests
{
  [SkippableFact]
  public void One_machine_block_runs_as_pasted_and_equals_one_process()
  {
    RequiredTool.Find("parallel", "parallel");
    RequiredTool.Find("ffmpeg", "ffmpeg");
    string page = File.ReadAllText(Path.Combine(RepoPaths.Root, "docs", "scale-out.md"));
    int section = page.IndexOf("\n## GNU parallel (one machine, or several over ssh)\n", StringComparison.Ordinal);
    Assert.True(section >= 0, "docs/scale-out.md has no section '## GNU parallel (one machine, or several over ssh)'");
    string block = ReadmeTests.ShellBlocks(page[section..]).First().Text;
    Assert.Contains("parallel --will-cite", block);
    Assert.Contains("--video orbit.mp4", block);

    using var dir = new TempDirectory();
    var env = SlurmRecipeTests.ProjectRoot(dir, new() { ["recipe.sh"] = block }, null, ("SIZE", "32x24"));
    var (code, output) = Shell.Run(dir.Path, env, TimeSpan.FromMinutes(8), "bash", "--noprofile", "--norc", "-e", "-o", "pipefail", "recipe.sh");
    Assert.True(code == 0, $"the block failed (exit {code}):\n{block}\n{output}");

    var (oneCode, _, error) = GrcisProcess.Run(dir.Path, "animate", "scripts/Orbit.cs", "-o", "one/out####.png", "--size", "32x24",
      "--spp", "16", "--video", "one.mp4", "-q");
    Assert.True(oneCode == 0, error);
    AnimateRun.AssertSameFiles(AnimateRun.Snapshot(dir.File("one")), AnimateRun.Snapshot(dir.File("frames")));
    Assert.Equal(File.ReadAllBytes(dir.File("one.mp4")), File.ReadAllBytes(dir.File("orbit.mp4")));
  }
}
