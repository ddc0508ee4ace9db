using System;

namespace GrCis.Cli;

/// <summary>A valid command that could not be carried out (e.g. output not writable); exit code <see cref="ExitCodes.Failure"/>.</summary>
public sealed class CliFailure : Exception
{
  public CliFailure(string message, Exception? inner = null) : base(message, inner) { }
}
