using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Runtime.InteropServices;
using System.Threading;
using Rendering.Execution;
using Utilities;

namespace GrCis.Cli.Watching;

/// <summary>
/// <c>--watch</c>: runs one pass of a command (a render), then waits for a save of a watched file (the script, its
/// modules, the data files the scene read) and runs the pass again, in the same process, so the compiler is warm and
/// an edit costs a compilation, not a start-up. Saves close together are one change (<see cref="Debounce"/>); a save
/// during a pass cancels it. A failed pass prints its error as a command would and the loop goes on (the last good
/// image stays, as a failed render writes nothing). Ctrl+C or SIGTERM ends the loop with <see cref="ExitCodes.Cancelled"/>.
/// </summary>
internal sealed class WatchLoop
{
  /// <summary>How long the watched files must stay quiet before the next pass (an editor's save is several writes).</summary>
  public static readonly TimeSpan Debounce = TimeSpan.FromMilliseconds(100);

  readonly CliEnvironment env;
  readonly IReadOnlyList<string> files;
  readonly IReadOnlyList<string> moduleFolders;
  readonly object sync = new();
  readonly AutoResetEvent changed = new(false);
  readonly Stopwatch clock = Stopwatch.StartNew();
  CancellationTokenSource? pass;
  TimeSpan lastChange;
  Timer? deadline;

  /// <param name="files">Files watched from the start (the script).</param>
  /// <param name="moduleFolders">Module folders: every <c>*.cs</c> below them is watched.</param>
  public WatchLoop(CliEnvironment env, IReadOnlyList<string> files, IReadOnlyList<string> moduleFolders)
  {
    this.env = env;
    this.files = files;
    this.moduleFolders = moduleFolders;
  }

  /// <summary>
  /// Runs passes until Ctrl+C or SIGTERM (then returns <see cref="ExitCodes.Cancelled"/>). A usage error in the first
  /// pass ends the loop with its code: the command line itself is wrong, no save will mend it.
  /// </summary>
  /// <param name="runPass">One pass, given an environment whose cancellation is the pass's; returns its exit code or throws as a command does.</param>
  public int Run(Func<CliEnvironment, int> runPass)
  {
    using var stop = CancellationTokenSource.CreateLinkedTokenSource(env.Cancel);
    using PosixSignalRegistration? term = env.OwnsProcess ? Terminate(stop) : null;
    using var watched = new WatchedFiles(OnChanged);
    foreach (string f in files)
      watched.AddFile(f);
    foreach (string m in moduleFolders)
      watched.AddModuleFolder(m);

    for (bool first = true; ; first = false)
    {
      var reads = new List<string>();
      int code = RunPass(runPass, reads, stop.Token);
      if (stop.IsCancellationRequested)
        return Stopped();
      if (first && code == ExitCodes.Usage)
        return code;
      // Files the scene read: a texture or a mesh edited is re-rendered too (failed passes read fewer; keep the earlier ones).
      foreach (string r in reads)
        watched.AddFile(r);
      env.Error.WriteLine($"grcis: watching {watched.FileCount} file{(watched.FileCount == 1 ? "" : "s")}" +
                          (moduleFolders.Count > 0 ? $" and {moduleFolders.Count} module folder{(moduleFolders.Count == 1 ? "" : "s")}" : "") +
                          "; save to render again, Ctrl+C to stop");
      env.Error.Flush();
      if (!WaitForChange(stop.Token))
        return Stopped();
    }
  }

  int RunPass(Func<CliEnvironment, int> runPass, List<string> reads, CancellationToken stop)
  {
    CancellationTokenSource cts;
    lock (sync)
    {
      pass = cts = CancellationTokenSource.CreateLinkedTokenSource(stop);
      // This pass renders every change seen so far (one save is several events); a later one cancels it and signals anew.
      changed.Reset();
    }
    try
    {
      CliEnvironment passEnv = env.WithCancel(cts.Token);
      using Interruption.Scope interruption = Interruption.Use(cts.Token);
      using DataFiles.LogScope log = DataFiles.LogReads(reads);
      try
      {
        return runPass(passEnv);
      }
      catch (Exception e)
      {
        return Program.Report(passEnv, e);
      }
      finally
      {
        env.Out.Flush();
        env.Error.Flush();
      }
    }
    finally
    {
      lock (sync)
        pass = null;
      cts.Dispose();
    }
  }

  void OnChanged(string path)
  {
    lock (sync)
    {
      lastChange = clock.Elapsed;
      // The pass under way renders what is now out of date.
      pass?.Cancel();
    }
    changed.Set();
  }

  /// <summary>Waits for a change and then for <see cref="Debounce"/> of quiet; false when the loop is to stop.</summary>
  bool WaitForChange(CancellationToken stop)
  {
    if (WaitHandle.WaitAny([changed, stop.WaitHandle]) != 0)
      return false;
    while (true)
    {
      TimeSpan quiet;
      lock (sync)
        quiet = clock.Elapsed - lastChange;
      if (quiet >= Debounce)
        return true;
      if (stop.WaitHandle.WaitOne(Debounce - quiet))
        return false;
    }
  }

  int Stopped()
  {
    env.Error.WriteLine("grcis: stopped watching");
    return ExitCodes.Cancelled;
  }

  /// <summary>SIGTERM (a closed terminal, <c>kill</c>) ends the loop as Ctrl+C does, forcefully after the same grace.</summary>
  PosixSignalRegistration? Terminate(CancellationTokenSource stop)
  {
    if (OperatingSystem.IsWindows())
      return null;
    return PosixSignalRegistration.Create(PosixSignal.SIGTERM, c =>
    {
      c.Cancel = true;
      stop.Cancel();
      // A pass stuck where cancellation does not reach (a script that sleeps) must not keep the process alive.
      deadline ??= new Timer(_ =>
      {
        env.Error.WriteLine("grcis: error: terminated; the scene did not stop in time; no file was left half-written");
        env.Error.Flush();
        Environment.Exit(ExitCodes.Cancelled);
      }, null, InterruptGuard.Grace, Timeout.InfiniteTimeSpan);
    });
  }
}
