using System;

namespace GrCis.Cli.Tests;

/// <summary>A fact that needs Unix file permissions to bite: skipped on Windows and for root (who may write anywhere).</summary>
internal sealed class UnixNonRootFactAttribute : FactAttribute
{
  public UnixNonRootFactAttribute()
  {
    if (OperatingSystem.IsWindows())
      Skip = "Unix permissions only";
    else if (Environment.UserName == "root")
      Skip = "root ignores directory permissions";
  }
}
