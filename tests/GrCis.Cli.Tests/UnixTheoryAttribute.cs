using System;

namespace GrCis.Cli.Tests;

/// <summary>A theory about Unix paths or permissions: skipped only on Windows.</summary>
internal sealed class UnixTheoryAttribute : TheoryAttribute
{
  public UnixTheoryAttribute()
  {
    if (OperatingSystem.IsWindows())
      Skip = "Unix only";
  }
}
