using System;

namespace GrCis.Studio;

/// <summary>The one sentence the page shows when the studio process ended and its supervisor started a new one.</summary>
internal static class WorkerEndings
{
  /// <summary>Why the supervisor ended a studio process that kept working after Stop.</summary>
  public static readonly string NotStopped = $"did not stop within {StudioSupervisor.StopGrace.TotalSeconds:0} s and was ended";

  /// <summary>Why the supervisor ended a studio process that did not answer it.</summary>
  public const string NotAnswering = "stopped answering and was ended";

  /// <summary>The supervisor itself is closing (not news for any page).</summary>
  public const string Closed = "was closed";

  /// <summary>
  /// <c>The render process ran out of memory; the studio restarted it.</c> and its kin: <paramref name="endedBecause"/>
  /// when the supervisor ended it, else what its exit code and last lines of error output (<paramref name="errors"/>)
  /// say: .NET prints <c>Stack overflow.</c> before it aborts (exit 134), an unhandled out-of-memory names
  /// <see cref="OutOfMemoryException"/>, and the kernel's out-of-memory killer sends SIGKILL (exit 137).
  /// </summary>
  public static string Sentence(string? endedBecause, int exitCode, string errors)
  {
    string what = endedBecause ??
      (errors.Contains("Stack overflow", StringComparison.Ordinal) ? "overflowed its stack"
      : errors.Contains("OutOfMemoryException", StringComparison.Ordinal) || errors.Contains("Out of memory", StringComparison.Ordinal) ||
        exitCode == 137 ? "ran out of memory"
      : $"ended unexpectedly (exit code {exitCode})");
    return $"The render process {what}; the studio restarted it.";
  }
}
