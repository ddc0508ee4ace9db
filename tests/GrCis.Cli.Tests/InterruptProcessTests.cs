using System;
using GrCis.TestSupport;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Threading;

namespace GrCis.Cli.Tests;

/// <summary>
/// Ctrl+C (SIGINT) ends <c>grcis</c> promptly with exit code 130 whatever a scene script does:
/// a script stuck in a loop while it builds the scene, or a class of the script stuck while rendering,
/// never looks at the cancellation token. The loop obeys Ctrl+C anyway (the compiler put an
/// interruption point in it), so the run ends cooperatively, before the forced exit, with one
/// error line, no image and no temporary file. A script blocked without a loop meets the forced exit.
/// </summary>
public class InterruptProcessTests
{
  static readonly string StuckWhileBuilding = StuckScripts.WhileBuilding("started");

  static readonly string StuckWhileRendering = StuckScripts.WhileRendering("started");

  [UnixFact]
  public void Sigint_ends_a_script_stuck_while_building_the_scene() => AssertInterrupted(StuckWhileBuilding, "render");

  [UnixFact]
  public void Sigint_ends_a_script_stuck_while_rendering() => AssertInterrupted(StuckWhileRendering, "render");

  [UnixFact]
  public void Sigint_ends_an_animation_whose_script_is_stuck() => AssertInterrupted(StuckWhileRendering, "animate");

  /// <summary>A sleep has no loop to interrupt: the forced exit after the grace period ends it.</summary>
  [UnixFact]
  public void Sigint_ends_a_script_blocked_without_a_loop_by_the_forced_exit() =>
    AssertInterrupted(StuckScripts.Camera + """

      System.IO.File.WriteAllText("started", "");
      System.Threading.Thread.Sleep(System.Threading.Timeout.Infinite);
      """, "render", forced: true);

  static void AssertInterrupted(string script, string command, bool forced = false)
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("stuck.cs"), script);
    string output = command == "render" ? "out.png" : "frames/f##.png";
    using Process p = GrcisProcess.Start(dir.Path, null, command, "stuck.cs", "-o", output, "--size", "16x12", "-q");

    var clock = Stopwatch.StartNew();
    while (!File.Exists(dir.File("started")) && !p.HasExited && clock.Elapsed < TimeSpan.FromMinutes(2))
      Thread.Sleep(20);
    if (p.HasExited)
      Assert.Fail("grcis ended before the script got stuck: " + p.StandardError.ReadToEnd());
    Thread.Sleep(200);   // inside the loop

    clock.Restart();
    using (Process kill = Process.Start("kill", ["-INT", p.Id.ToString(System.Globalization.CultureInfo.InvariantCulture)]))
      kill.WaitForExit();
    bool ended = p.WaitForExit(15_000);
    TimeSpan took = clock.Elapsed;
    if (!ended)
      p.Kill(entireProcessTree: true);
    Assert.True(ended, "grcis still running 15 s after SIGINT");
    Assert.True(took < InterruptGuard.Grace + TimeSpan.FromSeconds(3), $"SIGINT took {took.TotalSeconds:0.0} s");

    Assert.Equal(ExitCodes.Cancelled, p.ExitCode);
    string[] errors = p.StandardError.ReadToEnd().Split('\n', StringSplitOptions.RemoveEmptyEntries);
    string line = Assert.Single(errors);
    if (forced)
    {
      Assert.True(took >= InterruptGuard.Grace - TimeSpan.FromMilliseconds(100), $"ended after {took.TotalSeconds:0.0} s, before the grace period");
      Assert.StartsWith("grcis: error: interrupted", line);
    }
    else
    {
      Assert.True(took < InterruptGuard.Grace, $"the loop did not obey Ctrl+C: {took.TotalSeconds:0.0} s, the forced exit ended it");
      Assert.StartsWith("grcis: error: cancelled", line);
    }
    Assert.DoesNotContain(Directory.GetFiles(dir.Path, "*", SearchOption.AllDirectories),
      f => f.EndsWith(".png", StringComparison.Ordinal) || f.Contains(".tmp-", StringComparison.Ordinal));
  }

  /// <summary><c>grcis studio</c> stops on SIGTERM (a service manager, <c>kill</c>, a closed terminal) as on Ctrl+C.</summary>
  [UnixTheory]
  [InlineData("INT")]
  [InlineData("TERM")]
  public void Studio_stops_cleanly_on_sigint_and_sigterm(string signal)
  {
    using var dir = new TempDirectory();
    using Process p = GrcisProcess.Start(dir.Path, null, "studio", "--port", "0", "--no-open", "--nodefault");
    string? url = p.StandardOutput.ReadLine();
    Assert.StartsWith("http://127.0.0.1:", url);

    var clock = Stopwatch.StartNew();
    using (Process kill = Process.Start("kill", ["-" + signal, p.Id.ToString(System.Globalization.CultureInfo.InvariantCulture)]))
      kill.WaitForExit();
    bool ended = p.WaitForExit(15_000);
    if (!ended)
      p.Kill(entireProcessTree: true);
    Assert.True(ended, $"grcis studio still running 15 s after SIG{signal}");
    Assert.Equal(ExitCodes.Cancelled, p.ExitCode);
    Assert.True(clock.Elapsed < TimeSpan.FromSeconds(5), $"SIG{signal} took {clock.Elapsed.TotalSeconds:0.0} s");
  }
}
