using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Threading;
using GrCis.TestSupport;

namespace GrCis.Cli.Tests;

/// <summary>
/// A one-node Slurm (munged, slurmctld, slurmd from Debian's slurm-wlm and munge) started by
/// <c>tests/tools/slurm-one-node.sh</c> in a temporary folder on first use, stopped on dispose.
/// Needs root; skips (or fails under <c>GRCIS_REQUIRE_TOOLS=1</c>) without the packages or root.
/// </summary>
public sealed class SlurmCluster : IDisposable
{
  readonly TempDirectory dir = new();
  readonly object sync = new();
  string? conf;

  /// <summary>The folder of <c>slurm.conf</c>, keys, state and the daemons' logs.</summary>
  public string Folder => dir.Path;

  /// <summary>Starts the cluster once; returns the <c>SLURM_CONF</c> path its commands need.</summary>
  public string Start()
  {
    // Debian installs the daemons in /usr/sbin, which a user's PATH may lack.
    string path = (Environment.GetEnvironmentVariable("PATH") ?? "") + ":/usr/sbin:/usr/bin";
    RequiredTool.Find("munged", "munge", path, RequiredTool.Required);
    foreach (string daemon in new[] { "slurmctld", "slurmd", "sbatch" })
      RequiredTool.Find(daemon, "slurm-wlm", path, RequiredTool.Required);
    if (!OperatingSystem.IsLinux() || Environment.UserName != "root")
    {
      const string message = "the one-node Slurm runs its daemons as root (as CI does); run the tests as root";
      if (RequiredTool.Required)
        throw new Xunit.Sdk.XunitException(message + $"; {RequiredTool.RequireVariable}=1, so this fails instead of skipping");
      throw new SkipException(message);
    }
    lock (sync)
    {
      if (conf != null)
        return conf;
      string script = Path.Combine(RepoPaths.Root, "tests", "tools", "slurm-one-node.sh");
      var (code, output) = Shell.Run(dir.Path, null, TimeSpan.FromMinutes(1), "bash", script, "start", dir.File("cluster"), "8");
      Assert.True(code == 0, $"slurm-one-node.sh start failed (exit {code}):\n{output}");
      string line = output.Split('\n').Single(l => l.StartsWith("SLURM_CONF=", StringComparison.Ordinal));
      conf = line["SLURM_CONF=".Length..].Trim();
      return conf;
    }
  }

  /// <summary>Runs a Slurm client command (squeue, scancel, scontrol …) on this cluster; its exit code and output.</summary>
  public (int Code, string Output) Command(string program, params string[] args) =>
    Shell.Run(dir.Path, new Dictionary<string, string?> { ["SLURM_CONF"] = Start() }, TimeSpan.FromMinutes(1), program, args);

  /// <summary>The state of a job or array task (<c>RUNNING</c>, <c>COMPLETED</c>, <c>CANCELLED</c> …), from scontrol.</summary>
  public string State(string job)
  {
    var (_, output) = Command("scontrol", "show", "job", job);
    string? state = output.Split([' ', '\n'], StringSplitOptions.RemoveEmptyEntries).FirstOrDefault(w => w.StartsWith("JobState=", StringComparison.Ordinal));
    return state?["JobState=".Length..] ?? "unknown: " + output.Trim();
  }

  /// <summary>Waits until no job of the cluster is pending or running; fails after <paramref name="limit"/>.</summary>
  public void WaitUntilIdle(TimeSpan limit)
  {
    var clock = Stopwatch.StartNew();
    string queue = "";
    while (clock.Elapsed < limit)
    {
      (_, queue) = Command("squeue", "-h", "-o", "%i %j %T %r");
      if (queue.Trim().Length == 0)
        return;
      Thread.Sleep(500);
    }
    Assert.Fail($"jobs still queued after {limit.TotalMinutes} minutes:\n{queue}");
  }

  public void Dispose()
  {
    if (conf != null)
      Shell.Run(dir.Path, null, TimeSpan.FromMinutes(1), "bash", Path.Combine(RepoPaths.Root, "tests", "tools", "slurm-one-node.sh"), "stop", dir.File("cluster"));
    dir.Dispose();
  }
}
