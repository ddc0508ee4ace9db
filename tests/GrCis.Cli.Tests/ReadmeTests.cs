using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;

namespace GrCis.Cli.Tests;

/// <summary>
/// README's shell blocks work as pasted: every <c>```sh</c> block is run verbatim with bash, in order, as a newcomer
/// runs them, unless the line before it says <c>&lt;!-- not run: why --&gt;</c> (the test suite itself, a server,
/// a synopsis with optional parts). The user is fresh (a temporary home: no tools, templates or NuGet settings of
/// their own); the NuGet package folder is the machine's, so nothing is downloaded that a build here did not need.
/// </summary>
/// <remarks>
/// A block that builds (names <c>GrCis.sln</c> or <c>--project</c>) runs in the repository root, as README says; the
/// files it writes there that were not there before (<c>artifacts/</c>, the image) are removed afterwards. Every
/// other block runs in one temporary folder, in which <c>scripts</c> is the repository's scripts folder.
/// </remarks>
[Collection(RepositoryPacking.Name)]
public class ReadmeTests
{
  internal sealed record ShellBlock(int Line, string Text, string? NotRun)
  {
    public bool NeedsRepository => Text.Contains("GrCis.sln", StringComparison.Ordinal) || Text.Contains("--project", StringComparison.Ordinal);

    /// <summary>What the block's <c>-o</c> options name: files (or folders) that exist after it ran.</summary>
    public IEnumerable<string> Outputs => Regex.Matches(Text, @"(?:^|\s)-o\s+(""[^""]+""|\S+)").Select(m => m.Groups[1].Value.Trim('"'));
  }

  static readonly Regex NotRunComment = new(@"^<!-- not run: (?<why>.+\S) -->$");

  /// <summary>The <c>```sh</c> blocks of a Markdown text, with the line of their fence (1-based).</summary>
  internal static List<ShellBlock> ShellBlocks(string markdown)
  {
    string[] lines = markdown.Split('\n').Select(l => l.TrimEnd('\r')).ToArray();
    var blocks = new List<ShellBlock>();
    for (int i = 0; i < lines.Length; i++)
    {
      if (!lines[i].StartsWith("```", StringComparison.Ordinal))
        continue;
      int start = i;
      bool sh = lines[i].Trim() == "```sh";
      for (i++; i < lines.Length && !lines[i].StartsWith("```", StringComparison.Ordinal); i++) { }
      if (!sh)
        continue;
      Match note = start > 0 ? NotRunComment.Match(lines[start - 1]) : Match.Empty;
      blocks.Add(new ShellBlock(start + 1, string.Join('\n', lines[(start + 1)..i]) + "\n", note.Success ? note.Groups["why"].Value : null));
    }
    return blocks;
  }

  static List<ShellBlock> ReadmeBlocks() => ShellBlocks(File.ReadAllText(Path.Combine(RepoPaths.Root, "README.md")));

  [Fact]
  public void Readme_runs_its_install_and_example_blocks_and_says_why_it_skips_others()
  {
    List<ShellBlock> blocks = ReadmeBlocks();
    List<ShellBlock> run = blocks.Where(b => b.NotRun == null).ToList();
    Assert.Contains(run, b => b.Text.Contains("dotnet tool install", StringComparison.Ordinal));
    Assert.Contains(run, b => b.Text.StartsWith("grcis list", StringComparison.Ordinal));
    Assert.Contains(run, b => b.Text.Contains("grcis render scripts/", StringComparison.Ordinal));
    // The install block comes before any block that runs grcis.
    Assert.Contains("dotnet tool install", run[0].Text, StringComparison.Ordinal);
    // A block with optional parts in brackets cannot be pasted: it is a synopsis, marked as not run.
    foreach (ShellBlock b in run)
      Assert.False(Regex.IsMatch(b.Text, @"\s\[-"), $"README.md:{b.Line}: a run block has an optional [--part]");
  }

  [Fact]
  public void Shell_blocks_are_found_with_their_notes()
  {
    const string text = "a\n```sh\necho 1\n```\n<!-- not run: a server -->\n```sh\nserve\n```\n```\ngrcis --help\n```\n";
    List<ShellBlock> blocks = ShellBlocks(text);
    Assert.Equal(2, blocks.Count);
    Assert.Equal((2, "echo 1\n", (string?)null), (blocks[0].Line, blocks[0].Text, blocks[0].NotRun));
    Assert.Equal((6, "serve\n", "a server"), (blocks[1].Line, blocks[1].Text, blocks[1].NotRun));
    Assert.Equal(new[] { "out dir/x.png", "b.pfm" },
                 new ShellBlock(1, "grcis render -o \"out dir/x.png\"\ngrcis render x -s 1x1 -o b.pfm --noise n.pfm\n", null).Outputs);
  }

  /// <summary>
  /// The expensive one: packs the solution, installs the tool and the template into a fresh home, then runs every
  /// example block with the installed <c>grcis</c> (several minutes on a small machine).
  /// </summary>
  [UnixFact]
  public void Readme_shell_blocks_run_as_pasted_in_a_fresh_home()
  {
    using var tmp = new TempDirectory();
    string home = Directory.CreateDirectory(tmp.File("home")).FullName;
    string work = Directory.CreateDirectory(tmp.File("work")).FullName;
    File.CreateSymbolicLink(Path.Combine(work, "scripts"), RepoPaths.Scripts);

    Dictionary<string, string?> env = PackagesTests.FreshHome(home);
    // The machine's package folder (restoring the repository into a fresh one would point its obj/ there), its
    // sources in the fresh user's NuGet.Config (where `dotnet nuget add source` adds the feed).
    env["NUGET_PACKAGES"] = GlobalPackagesFolder();
    string userConfig = Path.Combine(home, ".nuget", "NuGet", "NuGet.Config");
    Directory.CreateDirectory(Path.GetDirectoryName(userConfig)!);
    File.WriteAllText(userConfig, PackagesTests.NuGetConfig(feed: null));
    // No build servers left running after the test.
    env["MSBUILDDISABLENODEREUSE"] = "1";
    env["DOTNET_CLI_USE_MSBUILD_SERVER"] = "0";
    env["UseSharedCompilation"] = "false";
    // grcis on PATH as README asks (~/.dotnet/tools); no grcis of the machine's user.
    string dotnetFolder = Path.IsPathRooted(PackagesTests.Dotnet) ? Path.GetDirectoryName(PackagesTests.Dotnet)! : "";
    IEnumerable<string> rest = (Environment.GetEnvironmentVariable("PATH") ?? "").Split(':', StringSplitOptions.RemoveEmptyEntries)
      .Where(d => !d.TrimEnd('/').EndsWith(".dotnet/tools", StringComparison.Ordinal));
    env["PATH"] = string.Join(':', new[] { Path.Combine(home, ".dotnet", "tools"), dotnetFolder }.Where(d => d.Length > 0).Concat(rest));

    var createdInRepository = new List<string>();
    try
    {
      foreach (ShellBlock block in ReadmeBlocks().Where(b => b.NotRun == null))
      {
        string folder = block.NeedsRepository ? RepoPaths.Root : work;
        string[] outputs = block.Outputs.Select(o => Path.GetFullPath(Path.Combine(folder, o))).ToArray();
        if (block.NeedsRepository)
          createdInRepository.AddRange(outputs.Where(o => !File.Exists(o) && !Directory.Exists(o)));
        string script = tmp.File($"block-{block.Line}.sh");
        File.WriteAllText(script, block.Text);
        (int code, string output) = Bash(folder, env, script, TimeSpan.FromMinutes(20));
        Assert.True(code == 0, $"README.md:{block.Line}: the block failed (exit {code}) in {(block.NeedsRepository ? "the repository root" : "a temporary folder")}:\n{block.Text}\n{output}");
        foreach (string o in outputs)
          Assert.True(File.Exists(o) || Directory.Exists(o), $"README.md:{block.Line}: {o} was not written\n{output}");
      }
      InstalledToolIsCompiledAheadOfTime(home);
    }
    finally
    {
      foreach (string created in createdInRepository)
      {
        if (Directory.Exists(created))
          Directory.Delete(created, recursive: true);
        else
          File.Delete(created);
      }
    }
  }

  /// <summary>
  /// What README's <c>dotnet tool install</c> gave is this machine's platform package of the tool (not the portable
  /// fallback), and its code, the library's and Roslyn's, is compiled ahead of time (ReadyToRun) with grcis's options
  /// and the static profile.
  /// </summary>
  static void InstalledToolIsCompiledAheadOfTime(string home)
  {
    string rid = System.Runtime.InteropServices.RuntimeInformation.RuntimeIdentifier;
    string store = Path.Combine(home, ".dotnet", "tools", ".store");
    string[] tools = Directory.GetFiles(store, "grcis.dll", SearchOption.AllDirectories);
    string tool = Assert.Single(tools);
    Assert.Contains($"{Path.DirectorySeparatorChar}grcis.cli.{rid}{Path.DirectorySeparatorChar}", tool, StringComparison.Ordinal);
    foreach (string dll in new[] { "grcis.dll", "GrCis.Rendering.dll", "GrCis.Hosting.dll", "Microsoft.CodeAnalysis.CSharp.dll" })
    {
      string path = Path.Combine(Path.GetDirectoryName(tool)!, dll);
      using var pe = new System.Reflection.PortableExecutable.PEReader(File.OpenRead(path));
      Assert.True(ToolPackageCheck.ReadyToRunTraits(pe) != null, $"{dll} of the installed tool is not ReadyToRun");
      // Compiled for this system and processor (the PE machine field a ReadyToRun image carries).
      Assert.Equal(ToolPackageCheck.ReadyToRunMachine(rid), (ushort)pe.PEHeaders.CoffHeader.Machine);
      // With grcis's options: inlining across assemblies, other assemblies' generic code in the image.
      ToolPackageCheck.CompiledAcrossAssemblies(pe, $"{dll} of the installed tool");
    }
    // The static profile of the training renders: in the library's image, and the instrumented tier turned off.
    using (var library = new System.Reflection.PortableExecutable.PEReader(File.OpenRead(Path.Combine(Path.GetDirectoryName(tool)!, "GrCis.Rendering.dll"))))
      Assert.True(ToolPackageCheck.ReadyToRunTraits(library) is { EmbedsProfile: true }, "the installed tool's GrCis.Rendering.dll embeds no profile");
    var config = System.Text.Json.Nodes.JsonNode.Parse(File.ReadAllText(Path.ChangeExtension(tool, ".runtimeconfig.json")))!;
    Assert.False(ExecutableTests.RuntimeOption(config, "System.Runtime.TieredPGO")?.GetValue<bool>() ?? true,
      "the installed tool's runtimeconfig keeps the instrumented tier (System.Runtime.TieredPGO)");
    Assert.False(ExecutableTests.RuntimeOption(config, "System.Diagnostics.Tracing.EventSource.IsSupported")?.GetValue<bool>() ?? true,
      "the installed tool's runtimeconfig builds the runtime's managed event sources at every start");
  }

  [Fact]
  public void Precompiled_assemblies_are_told_from_plain_ones()
  {
    Assert.True(IsReadyToRun(typeof(object).Assembly.Location)); // the runtime's own, compiled ahead of time
    Assert.False(IsReadyToRun(typeof(ReadmeTests).Assembly.Location));

    static bool IsReadyToRun(string dll)
    {
      using var pe = new System.Reflection.PortableExecutable.PEReader(File.OpenRead(dll));
      return ToolPackageCheck.ReadyToRunTraits(pe) != null;
    }
  }

  internal static string GlobalPackagesFolder()
  {
    (int code, string output) = PackagesTests.Exec(Path.GetTempPath(), null, PackagesTests.Dotnet, "nuget", "locals", "global-packages", "--list");
    Assert.True(code == 0, output);
    Match m = Regex.Match(output, @"global-packages:\s*(\S.*\S)");
    Assert.True(m.Success, output);
    return m.Groups[1].Value;
  }

  static (int Code, string Output) Bash(string folder, Dictionary<string, string?> env, string script, TimeSpan limit) =>
    Shell.Run(folder, env, limit, "bash", "--noprofile", "--norc", "-e", "-o", "pipefail", script);
}
