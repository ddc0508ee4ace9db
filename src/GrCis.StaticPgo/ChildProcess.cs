using System;
using System.Diagnostics;
using System.Threading.Tasks;

namespace GrCis.StaticPgo;

/// <summary>Runs a program to its end with its output captured; a failure throws with that output.</summary>
internal static class ChildProcess
{
  /// <param name="start">The program, its arguments and environment (output redirection is set here).</param>
  /// <param name="what">What failed, for the message: "training run 'grcis render …'".</param>
  public static void Run(ProcessStartInfo start, string what)
  {
    start.RedirectStandardOutput = true;
    start.RedirectStandardError = true;
    using Process process = Process.Start(start) ?? throw new InvalidOperationException($"could not start {start.FileName}");
    Task<string> stderr = process.StandardError.ReadToEndAsync();
    string stdout = process.StandardOutput.ReadToEnd();
    process.WaitForExit();
    if (process.ExitCode != 0)
      throw new InvalidOperationException($"{what} failed (exit {process.ExitCode}):\n{stdout}{stderr.Result}");
  }
}
