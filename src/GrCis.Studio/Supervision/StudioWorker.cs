using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Threading;
using System.Threading.Tasks;

namespace GrCis.Studio;

/// <summary>
/// One studio process that a <see cref="StudioSupervisor"/> runs: started, its port read from the URL it prints, its
/// error output passed on (and its last lines kept, which tell a stack overflow from an out-of-memory), and its end
/// explained in one sentence (<see cref="WorkerEndings"/>).
/// </summary>
internal sealed class StudioWorker : IDisposable
{
  const int KeptLines = 40;

  readonly Process process;
  readonly Queue<string> lastErrors = new();
  readonly Task errorsRead;
  readonly TaskCompletionSource exited = new(TaskCreationOptions.RunContinuationsAsynchronously);
  string? endedBecause;
  bool overflowed;

  StudioWorker(Process process, TextWriter errors)
  {
    this.process = process;
    errorsRead = Task.Run(async () =>
    {
      while (await process.StandardError.ReadLineAsync().ConfigureAwait(false) is string line)
      {
        lock (lastErrors)
        {
          // The runtime's "Stack overflow." comes before a long stack trace: kept apart, it outlives the kept tail.
          if (line.StartsWith("Stack overflow", StringComparison.Ordinal))
            overflowed = true;
          lastErrors.Enqueue(line);
          if (lastErrors.Count > KeptLines)
            lastErrors.Dequeue();
        }
        lock (errors)
        {
          errors.WriteLine(line);
          errors.Flush();
        }
      }
    });
    process.EnableRaisingEvents = true;
    process.Exited += (_, _) => exited.TrySetResult();
    if (process.HasExited)
      exited.TrySetResult();
  }

  /// <summary>The port the studio process listens on (on 127.0.0.1).</summary>
  public int Port { get; private set; }

  /// <summary>Where requests are forwarded to.</summary>
  public string Prefix => FormattableString.Invariant($"http://127.0.0.1:{Port}/");

  /// <summary>Completes when the process has ended.</summary>
  public Task Exited => exited.Task;

  public int ProcessId => process.Id;

  /// <summary>
  /// Starts the studio process and waits until it listens (it prints its URL); its standard input stays open, so a
  /// studio process whose supervisor died (its input ends) ends too.
  /// </summary>
  /// <exception cref="InvalidOperationException">The process ended, or printed no URL within <paramref name="timeout"/>; the message says why.</exception>
  public static async Task<StudioWorker> StartAsync(ProcessStartInfo start, TextWriter errors, TimeSpan timeout, CancellationToken cancel)
  {
    start.RedirectStandardInput = true;
    start.RedirectStandardOutput = true;
    start.RedirectStandardError = true;
    start.UseShellExecute = false;
    var worker = new StudioWorker(Process.Start(start) ?? throw new InvalidOperationException("the studio process did not start"), errors);
    try
    {
      using var waiting = CancellationTokenSource.CreateLinkedTokenSource(cancel);
      waiting.CancelAfter(timeout);
      string? line = await worker.process.StandardOutput.ReadLineAsync(waiting.Token).ConfigureAwait(false);
      if (line == null || !Uri.TryCreate(line.Trim(), UriKind.Absolute, out Uri? url))
      {
        await worker.Exited.WaitAsync(TimeSpan.FromSeconds(5), CancellationToken.None).ConfigureAwait(false);
        throw new InvalidOperationException(worker.process.HasExited
          ? $"the studio process ended before it listened (exit code {worker.process.ExitCode})"
          : "the studio process printed no URL");
      }
      worker.Port = url.Port;
      // Nothing more comes on its output; read it so it can never fill up.
      _ = worker.process.StandardOutput.ReadToEndAsync(CancellationToken.None);
      return worker;
    }
    catch (Exception e) when (e is OperationCanceledException or TimeoutException && !cancel.IsCancellationRequested)
    {
      worker.Dispose();
      throw new InvalidOperationException($"the studio process did not start listening within {timeout.TotalSeconds:0} s");
    }
    catch
    {
      worker.Dispose();
      throw;
    }
  }

  /// <summary>Ends the process (and its children) and remembers why: <see cref="Explain"/> then says so.</summary>
  public void End(string because)
  {
    Interlocked.CompareExchange(ref endedBecause, because, null);
    try
    {
      process.Kill(entireProcessTree: true);
    }
    catch (InvalidOperationException)
    {
      // It had ended already.
    }
  }

  /// <summary>Why the process ended, for the page (after <see cref="Exited"/>).</summary>
  public string Explain()
  {
    // Its last words arrive after its end: wait a moment for them.
    errorsRead.Wait(TimeSpan.FromSeconds(2));
    string tail;
    lock (lastErrors)
      tail = (overflowed ? "Stack overflow.\n" : "") + string.Join('\n', lastErrors);
    int code = process.HasExited ? process.ExitCode : 0;
    return WorkerEndings.Sentence(endedBecause, code, tail);
  }

  public void Dispose()
  {
    End(WorkerEndings.Closed);
    process.Dispose();
  }
}
