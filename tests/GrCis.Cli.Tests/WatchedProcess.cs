using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.Linq;
using System.Threading;

namespace GrCis.Cli.Tests;

/// <summary>A running <c>grcis … --watch</c> whose output lines are collected as they come, to wait for the next pass.</summary>
internal sealed class WatchedProcess : IDisposable
{
  static readonly TimeSpan Patience = TimeSpan.FromMinutes(2);

  readonly Process process;
  readonly List<string> outLines = new();
  readonly List<string> errorLines = new();
  readonly object sync = new();

  public WatchedProcess(string workingDirectory, params string[] args)
  {
    process = GrcisProcess.Start(workingDirectory, null, args);
    process.OutputDataReceived += (_, e) => Add(outLines, e.Data);
    process.ErrorDataReceived += (_, e) => Add(errorLines, e.Data);
    process.BeginOutputReadLine();
    process.BeginErrorReadLine();
  }

  public Process Process => process;

  public string Error
  {
    get
    {
      lock (sync)
        return string.Join("\n", errorLines);
    }
  }

  public string Out
  {
    get
    {
      lock (sync)
        return string.Join("\n", outLines);
    }
  }

  /// <summary>Lines of stderr announcing that a pass ended and the files are watched.</summary>
  public int Passes => Count(errorLines, l => l.StartsWith("grcis: watching", StringComparison.Ordinal));

  /// <summary>"wrote …" lines: images written.</summary>
  public int Images => Count(outLines, l => l.StartsWith("wrote ", StringComparison.Ordinal));

  /// <summary>
  /// Waits until <paramref name="passes"/> passes have ended and <paramref name="images"/> images were reported (fails the
  /// test on exit or after two minutes). Both counts: stdout and stderr are read apart, either may come in first.
  /// </summary>
  public void WaitForPasses(int passes, int images)
  {
    var clock = Stopwatch.StartNew();
    while (Passes < passes || Images < images)
    {
      if (process.HasExited)
        Assert.Fail($"grcis --watch ended (code {process.ExitCode}) before pass {passes}:\n{Out}\n{Error}");
      if (clock.Elapsed > Patience)
        Assert.Fail($"no pass {passes} within {Patience.TotalMinutes} minutes:\n{Out}\n{Error}");
      Thread.Sleep(20);
    }
  }

  /// <summary>Sends the signal and returns the exit code (fails the test when the process is still running 15 s later).</summary>
  public int Signal(string signal)
  {
    using (Process kill = Process.Start("kill", ["-" + signal, process.Id.ToString(CultureInfo.InvariantCulture)])!)
      kill.WaitForExit();
    bool ended = process.WaitForExit(15_000);
    if (!ended)
      process.Kill(entireProcessTree: true);
    Assert.True(ended, $"grcis --watch still running 15 s after SIG{signal}");
    process.WaitForExit();   // the output's last lines
    return process.ExitCode;
  }

  void Add(List<string> lines, string? line)
  {
    if (line != null)
      lock (sync)
        lines.Add(line);
  }

  int Count(List<string> lines, Func<string, bool> which)
  {
    lock (sync)
      return lines.Count(which);
  }

  public void Dispose()
  {
    if (!process.HasExited)
      process.Kill(entireProcessTree: true);
    process.Dispose();
  }
}
