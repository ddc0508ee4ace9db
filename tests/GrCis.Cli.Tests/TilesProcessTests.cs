using System;
using System.IO;
using System.Linq;
using GrCis.TestSupport;

namespace GrCis.Cli.Tests;

/// <summary>The GNU parallel recipe of docs/scale-out.md for stills, run as real processes on this machine.</summary>
public class TilesProcessTests
{
  [SkippableFact]
  public void Gnu_parallel_renders_the_parts_and_merge_gives_the_one_process_png()
  {
    string parallel = RequiredTool.Find("parallel", "parallel");
    using var dir = new TempDirectory();
    string[] render = ["render", "Toroids", "--size", "120x90", "--spp", "4", "--seed", "5", "-q"];

    var (code, _, error) = GrcisProcess.Run(dir.Path, [.. render, "-o", "whole.png"]);
    Assert.True(code == 0, error);

    // One job per part index, {} is the index (local jobs; --sshlogin spreads the same command over hosts).
    var (pcode, stdout, perror) = GrcisProcess.RunParallel(parallel, dir.Path, 3, [.. render, "--tiles", "{}/3", "-o", "part{}.grcis-part"]);
    Assert.True(pcode == 0, $"parallel exited {pcode}: {perror}");
    Assert.Equal("", stdout);   // -q: nothing printed on success
    Assert.Equal("", perror);

    var (mcode, mout, merror) = GrcisProcess.Run(dir.Path, "merge", "part0.grcis-part", "part1.grcis-part", "part2.grcis-part", "-o", "merged.png");
    Assert.True(mcode == 0, merror);
    Assert.Contains("from 3 parts", mout);
    Assert.Equal(File.ReadAllBytes(dir.File("whole.png")), File.ReadAllBytes(dir.File("merged.png")));
  }
}
