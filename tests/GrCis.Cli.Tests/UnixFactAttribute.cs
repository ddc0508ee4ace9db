using System;

namespace GrCis.Cli.Tests;

/// <summary>A fact that needs Unix file permissions: skipped only on Windows (root is handled by the test itself).</summary>
internal sealed class UnixFactAttribute : FactAttribute
{
  public UnixFactAttribute()
  {
    if (OperatingSystem.IsWindows())
      Skip = "Unix permissions only";
  }
}
