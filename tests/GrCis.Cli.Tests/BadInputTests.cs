using System;
using System.IO;

namespace GrCis.Cli.Tests;

/// <summary>Every mistake a user can make: one line on stderr, the right exit code, and no file (not even a temporary one).</summary>
public class BadInputTests
{
  static void AssertRejected(CliRun run, TempDirectory dir, int exitCode, string fragment)
  {
    Assert.Equal(exitCode, run.ExitCode);
    string line = Assert.Single(run.ErrorLines);
    Assert.StartsWith("grcis: error: ", line);
    Assert.Contains(fragment, line, StringComparison.OrdinalIgnoreCase);
    Assert.Equal("", run.Out);
    Assert.Empty(dir.AllFiles());
  }

  [Theory]
  [InlineData("No such scene", "unknown scene 'No such scene'")]
  [InlineData("Five bals", "did you mean 'Five balls'?")]
  [InlineData("plane sphere", "did you mean 'Sphere on the plane'?")]
  public void Unknown_scene_is_a_usage_error_with_suggestions(string scene, string fragment)
  {
    using var dir = new TempDirectory();
    AssertRejected(CliRun.Of(dir.Path, "render", scene, "-o", "x.png"), dir, ExitCodes.Usage, fragment);
  }

  [Theory]
  [InlineData("0x480")]
  [InlineData("640x0")]
  [InlineData("-5x10")]
  [InlineData("abc")]
  [InlineData("640x")]
  [InlineData("x480")]
  [InlineData("640*480")]
  [InlineData("99999999x99999999")]
  public void Non_positive_or_malformed_size_is_a_usage_error(string size)
  {
    using var dir = new TempDirectory();
    AssertRejected(CliRun.Of(dir.Path, "render", "--size", size, "-o", "x.png"), dir, ExitCodes.Usage, "--size");
  }

  [Theory]
  [InlineData("0")]
  [InlineData("-3")]
  [InlineData("many")]
  public void Spp_below_one_or_not_a_number_is_a_usage_error(string spp)
  {
    using var dir = new TempDirectory();
    AssertRejected(CliRun.Of(dir.Path, "render", "--spp", spp, "-o", "x.png"), dir, ExitCodes.Usage, "spp");
  }

  [Theory]
  [InlineData("--jitter", "1.5")]
  [InlineData("--gamma", "0")]
  [InlineData("--threads", "-1")]
  public void Out_of_range_values_are_usage_errors(string option, string value)
  {
    using var dir = new TempDirectory();
    AssertRejected(CliRun.Of(dir.Path, "render", option, value, "-o", "x.png"), dir, ExitCodes.Usage, option);
  }

  [Theory]
  [InlineData("--bogus")]
  [InlineData("--spp")]
  public void Unknown_or_incomplete_options_are_usage_errors(string arg)
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", "-o", "x.png", arg);
    AssertRejected(run, dir, ExitCodes.Usage, "");
  }

  [Fact]
  public void Unsupported_output_extension_is_a_usage_error()
  {
    using var dir = new TempDirectory();
    AssertRejected(CliRun.Of(dir.Path, "render", "-o", "x.jpg"), dir, ExitCodes.Usage, ".jpg");
  }

  [Fact]
  public void Output_in_a_missing_directory_is_not_created_when_the_render_fails()
  {
    // The folder is made only when the image is saved (RenderCommandTests: it is made then).
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("broken.cs"), "this is not C#\n");
    CliRun run = CliRun.Of(dir.Path, "render", "broken.cs", "-o", Path.Combine("missing", "deeper", "x.png"), "-q");
    Assert.Equal(ExitCodes.Failure, run.ExitCode);
    Assert.Equal("", run.Out);
    Assert.False(Directory.Exists(dir.File("missing")));
    Assert.Equal(new[] { dir.File("broken.cs") }, dir.AllFiles());
  }

  [Fact]
  public void Output_path_that_is_a_directory_fails()
  {
    using var dir = new TempDirectory();
    Directory.CreateDirectory(dir.File("taken.png"));
    CliRun run = CliRun.Of(dir.Path, "render", "-o", "taken.png", "--size", "8x8");
    AssertRejected(run, dir, ExitCodes.Failure, "is a directory");
  }

  [Fact]
  public void Output_below_a_regular_file_fails()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("plain"), "x");
    CliRun run = CliRun.Of(dir.Path, "render", "-o", Path.Combine("plain", "x.png"), "--size", "8x8");
    Assert.Equal(ExitCodes.Failure, run.ExitCode);
    Assert.StartsWith("grcis: error: cannot write", Assert.Single(run.ErrorLines));
    Assert.Equal(new[] { dir.File("plain") }, dir.AllFiles());
  }

  [UnixFact]
  public void Output_in_a_read_only_directory_fails_and_leaves_no_temporary_file()
  {
    using var dir = new TempDirectory();
    string target;
    if (Environment.UserName == "root")
    {
      // Root writes through directory permissions; sysfs refuses new files even to root.
      target = Path.Combine("/sys", "grcis-test.png");
    }
    else
    {
      string ro = dir.File("ro");
      Directory.CreateDirectory(ro);
      File.SetUnixFileMode(ro, UnixFileMode.UserRead | UnixFileMode.UserExecute);
      target = Path.Combine(ro, "x.png");
    }
    CliRun run = CliRun.Of(dir.Path, "render", "-o", target, "--size", "8x8");
    Assert.Equal(ExitCodes.Failure, run.ExitCode);
    string line = Assert.Single(run.ErrorLines);
    Assert.Contains("permission denied", line, StringComparison.OrdinalIgnoreCase);
    Assert.False(File.Exists(target));
    Assert.Empty(Directory.GetFiles(Path.GetDirectoryName(target)!, "*grcis-test*"));
    Assert.Empty(dir.AllFiles());
  }

  [Fact]
  public void No_command_is_a_usage_error()
  {
    using var dir = new TempDirectory();
    AssertRejected(CliRun.Of(dir.Path), dir, ExitCodes.Usage, "command");
  }

  [Fact]
  public void Missing_scene_script_is_a_usage_error()
  {
    using var dir = new TempDirectory();
    AssertRejected(CliRun.Of(dir.Path, "render", "nothere.cs", "-o", "x.png"), dir, ExitCodes.Usage, "nothere.cs");
  }
}
