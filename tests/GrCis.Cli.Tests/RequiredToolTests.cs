using System;
using System.IO;
using GrCis.TestSupport;
using SkipException = Xunit.SkipException;
using XunitException = Xunit.Sdk.XunitException;

namespace GrCis.Cli.Tests;

/// <summary>The rule every tool-dependent test follows: skip naming the package, or fail when GRCIS_REQUIRE_TOOLS=1.</summary>
public class RequiredToolTests
{
  [Fact]
  public void Missing_tool_skips_with_a_message_naming_the_debian_package()
  {
    using var dir = new TempDirectory();
    var skip = Assert.Throws<SkipException>(() => RequiredTool.Find("grcis-no-such-tool", "grcis-pkg", dir.Path, required: false));
    Assert.Contains("'grcis-no-such-tool' is not installed", skip.Message);
    Assert.Contains("Debian package 'grcis-pkg'", skip.Message);
  }

  [Fact]
  public void Missing_tool_fails_instead_when_tools_are_required()
  {
    using var dir = new TempDirectory();
    var failure = Assert.ThrowsAny<XunitException>(() => RequiredTool.Find("grcis-no-such-tool", "grcis-pkg", dir.Path, required: true));
    Assert.IsNotType<SkipException>(failure);
    Assert.Contains("Debian package 'grcis-pkg'", failure.Message);
    Assert.Contains("GRCIS_REQUIRE_TOOLS=1", failure.Message);
  }

  [Fact]
  public void Present_executable_is_found_and_a_non_executable_file_is_not()
  {
    using var dir = new TempDirectory();
    string tool = dir.File("grcis-tool");
    File.WriteAllText(tool, "#!/bin/sh\n");
    if (!OperatingSystem.IsWindows())
    {
      File.SetUnixFileMode(tool, UnixFileMode.UserRead | UnixFileMode.UserWrite);
      Assert.Null(RequiredTool.OnPath("grcis-tool", dir.Path));
      File.SetUnixFileMode(tool, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute);
    }
    string path = "/no/such/dir" + Path.PathSeparator + dir.Path;
    Assert.Equal(tool, RequiredTool.Find("grcis-tool", "grcis-pkg", path, required: true));
  }
}
