using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;

namespace GrCis.Cli.Tests;

/// <summary>
/// What a render node or container needs (docs/scale-out.md): the Dockerfile the page shows is the repository's,
/// and the built grcis runs on a .NET installation that holds exactly the shared runtimes of that image's final
/// stage, and not on the base runtime alone.
/// </summary>
public class NodeRuntimeTests
{
  /// <summary>The shared runtimes each official .NET image holds (runtime-deps: none, the app brings its own).</summary>
  static readonly Dictionary<string, string[]> ImageRuntimes = new()
  {
    ["mcr.microsoft.com/dotnet/runtime-deps"] = [],
    ["mcr.microsoft.com/dotnet/runtime"] = ["Microsoft.NETCore.App"],
    ["mcr.microsoft.com/dotnet/aspnet"] = ["Microsoft.NETCore.App", "Microsoft.AspNetCore.App"],
  };

  static string Dockerfile => File.ReadAllText(Path.Combine(RepoPaths.Root, "Dockerfile"));

  /// <summary>The image of the last <c>FROM</c> (the stage that runs), without its tag.</summary>
  static string FinalImage(string dockerfile) =>
    Regex.Matches(dockerfile, @"^FROM\s+(\S+?)(:\S+)?(\s+AS\s+\S+)?\s*$", RegexOptions.Multiline).Last().Groups[1].Value;

  [Fact]
  public void The_page_shows_the_repository_Dockerfile_and_dockerignore_keeps_build_outputs_out()
  {
    string page = File.ReadAllText(Path.Combine(RepoPaths.Root, "docs", "scale-out.md"));
    Match block = Regex.Match(page, "```dockerfile\n(.*?)```", RegexOptions.Singleline);
    Assert.True(block.Success, "docs/scale-out.md has no dockerfile block");
    Assert.Equal(Dockerfile, block.Groups[1].Value);
    Assert.Equal("mcr.microsoft.com/dotnet/aspnet", FinalImage(Dockerfile));

    string[] ignored = File.ReadAllLines(Path.Combine(RepoPaths.Root, ".dockerignore"));
    Assert.Contains("**/bin/", ignored);
    Assert.Contains("**/obj/", ignored);
  }

  [UnixFact]
  public void Built_grcis_renders_on_exactly_the_runtimes_of_the_images_final_stage()
  {
    using var dir = new TempDirectory();
    string root = DotnetRoot(dir, "image", ImageRuntimes[FinalImage(Dockerfile)]);
    var (code, output) = RunOn(root, dir, "render", "--size", "16x12", "-o", "node.png", "-q");
    Assert.True(code == 0, output);
    Assert.Equal("", output);

    var (expectedCode, _, error) = GrcisProcess.Run(dir.Path, "render", "--size", "16x12", "-o", "expected.png", "-q");
    Assert.True(expectedCode == 0, error);
    Assert.Equal(File.ReadAllBytes(dir.File("expected.png")), File.ReadAllBytes(dir.File("node.png")));
  }

  [UnixFact]
  public void On_the_base_runtime_alone_grcis_does_not_start_and_says_what_is_missing()
  {
    using var dir = new TempDirectory();
    string root = DotnetRoot(dir, "base", ImageRuntimes["mcr.microsoft.com/dotnet/runtime"]);
    var (code, output) = RunOn(root, dir, "render", "--size", "16x12", "-o", "node.png", "-q");
    Assert.Equal(150, code);
    Assert.Contains("Microsoft.AspNetCore.App", output);
    Assert.False(File.Exists(dir.File("node.png")));
  }

  /// <summary>
  /// A .NET installation with only <paramref name="runtimes"/>: the machine's host (copied, so it looks for
  /// frameworks beside itself, not beside the machine's) and links to the machine's runtimes of those names.
  /// </summary>
  static string DotnetRoot(TempDirectory dir, string name, string[] runtimes)
  {
    string machine = MachineDotnetRoot();
    string root = Directory.CreateDirectory(dir.File(name)).FullName;
    File.Copy(Path.Combine(machine, "dotnet"), Path.Combine(root, "dotnet"));
    File.SetUnixFileMode(Path.Combine(root, "dotnet"), (UnixFileMode)0b111_101_101);
    CopyTree(Path.Combine(machine, "host"), Path.Combine(root, "host"));
    foreach (string runtime in runtimes)
    {
      string shared = Directory.CreateDirectory(Path.Combine(root, "shared", runtime)).FullName;
      foreach (string version in Directory.GetDirectories(Path.Combine(machine, "shared", runtime)))
        Directory.CreateSymbolicLink(Path.Combine(shared, Path.GetFileName(version)), version);
    }
    return root;
  }

  static string MachineDotnetRoot()
  {
    string host = GrcisProcess.Dotnet;
    if (!Path.IsPathRooted(host))
      host = (Environment.GetEnvironmentVariable("PATH") ?? "").Split(':').Select(d => Path.Combine(d, host)).First(File.Exists);
    string real = new FileInfo(host).ResolveLinkTarget(returnFinalTarget: true)?.FullName ?? host;
    return Path.GetDirectoryName(real)!;
  }

  static void CopyTree(string from, string to)
  {
    Directory.CreateDirectory(to);
    foreach (string f in Directory.GetFiles(from))
      File.Copy(f, Path.Combine(to, Path.GetFileName(f)));
    foreach (string d in Directory.GetDirectories(from))
      CopyTree(d, Path.Combine(to, Path.GetFileName(d)));
  }

  /// <summary>Runs the built grcis.dll with the host of <paramref name="root"/>, which sees no other .NET.</summary>
  static (int Code, string Output) RunOn(string root, TempDirectory dir, params string[] args)
  {
    var env = new Dictionary<string, string?>
    {
      ["DOTNET_ROOT"] = root,
      ["DOTNET_ROOT_X64"] = null,
      ["DOTNET_HOST_PATH"] = null,
      ["DOTNET_MULTILEVEL_LOOKUP"] = "0",
      ["DOTNET_ROLL_FORWARD"] = null,
    };
    return Shell.Run(dir.Path, env, TimeSpan.FromMinutes(3), Path.Combine(root, "dotnet"), ["exec", GrcisProcess.Dll, .. args]);
  }
}
