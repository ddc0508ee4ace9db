using System;

namespace GrCis.Cli;

/// <summary>A mistake in the command line; reported as one line with exit code <see cref="ExitCodes.Usage"/>.</summary>
public sealed class UsageException : Exception
{
  public UsageException(string message) : base(message) { }
}
