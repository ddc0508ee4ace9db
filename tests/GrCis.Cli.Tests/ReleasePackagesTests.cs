using System;
using System.Collections;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json.Nodes;
using System.Xml.Linq;

namespace GrCis.Cli.Tests;

/// <summary>
/// The release set of tool packages (every platform of <c>GrCisReleaseRids</c>, docs/performance.md "The release
/// packages") can be made here, within CI's time: the tool restores for all of them (runtime, launcher and
/// ReadyToRun compiler packs found) and a small tool packs for a foreign platform with the same settings, its code
/// compiled for that platform. The full release pack (minutes) is the maintainer's; its result is checked by
/// <see cref="Release_artifacts_hold_every_platforms_ReadyToRun_tool"/> when <c>GRCIS_RELEASE_ARTIFACTS</c> names it.
/// </summary>
[Collection(RepositoryPacking.Name)]
public class ReleasePackagesTests
{
  static string ToolProps => Path.Combine(RepoPaths.Root, "src", "GrCis.Cli", "ToolPackages.props");

  /// <summary>The platforms a release packs, as the tool's packaging settings list them.</summary>
  internal static string[] ReleaseRids() =>
    XDocument.Load(ToolProps).Descendants("GrCisReleaseRids").Single().Value.Split(';', StringSplitOptions.TrimEntries);

  [Fact]
  public void Release_lists_the_main_platforms_and_the_portable_fallback()
  {
    string[] rids = ReleaseRids();
    foreach (string rid in new[] { "linux-x64", "linux-arm64", "win-x64", "osx-arm64", "any" })
      Assert.Contains(rid, rids);
    Assert.Equal(rids.Length, rids.Distinct().Count());
  }

  /// <summary>The release recipe's block in docs/performance.md ("The release packages"), its lines.</summary>
  internal static string[] ReleaseRecipe()
  {
    string page = File.ReadAllText(Path.Combine(RepoPaths.Root, "docs", "performance.md"));
    int section = page.IndexOf("### The release packages", StringComparison.Ordinal);
    Assert.True(section >= 0, "docs/performance.md has no section \"The release packages\"");
    return ReadmeTests.ShellBlocks(page[section..]).First().Text.Split('\n', StringSplitOptions.RemoveEmptyEntries);
  }

  [Fact]
  public void Release_recipe_packs_the_tool_and_checks_the_packages_with_this_class()
  {
    string[] recipe = ReleaseRecipe();
    Assert.StartsWith("dotnet pack src/GrCis.Cli -c Release ", recipe[0], StringComparison.Ordinal);
    Assert.Contains("-p:GrCisToolRids=release", recipe[0].Split(' '));
    Assert.Contains("GRCIS_RELEASE_ARTIFACTS=", recipe[1], StringComparison.Ordinal);
    Assert.EndsWith($"--filter {nameof(ReleasePackagesTests)}", recipe[1], StringComparison.Ordinal);
  }

  [Fact]
  public void Release_platforms_restore_with_their_runtime_launcher_and_compiler_packs()
  {
    using var tmp = new TempDirectory();
    // The recipe's properties; only the tool's restore, written to a scratch folder: the repository's obj/ (which
    // tests build from) is left alone.
    string[] properties = ReleaseRecipe()[0].Split(' ').Where(a => a.StartsWith("-p:", StringComparison.Ordinal)).ToArray();
    (int code, string output) = Dotnet(RepoPaths.Root, ["restore", "src/GrCis.Cli", .. properties, "-p:RestoreRecursive=false",
                                       $"-p:RestoreOutputPath={tmp.Path}/", "--force", "--disable-build-servers"]);
    Assert.True(code == 0, "the release restore failed:\n" + output);

    JsonNode assets = JsonNode.Parse(File.ReadAllText(tmp.File("project.assets.json")))!;
    string[] targets = assets["targets"]!.AsObject().Select(t => t.Key).ToArray();
    string[] downloads = assets["project"]!["frameworks"]!["net10.0"]!["downloadDependencies"]!.AsArray()
      .Select(d => (string)d!["name"]!).ToArray();
    string host = System.Runtime.InteropServices.RuntimeInformation.RuntimeIdentifier;
    foreach (string rid in ReleaseRids())
    {
      Assert.Contains($"net10.0/{rid}", targets);
      if (rid == "any")
        continue;
      Assert.Contains($"Microsoft.NETCore.App.Runtime.{rid}", downloads);
      Assert.Contains($"Microsoft.AspNetCore.App.Runtime.{rid}", downloads);
      // The SDK carries its own platform's launcher; every other comes as a package.
      if (rid != host)
        Assert.Contains($"Microsoft.NETCore.App.Host.{rid}", downloads);
    }
    Assert.Contains(downloads, d => d.StartsWith("Microsoft.NETCore.App.Crossgen2.", StringComparison.Ordinal));
  }

  [Fact]
  public void A_tool_packs_for_a_foreign_platform_compiled_for_it()
  {
    const string Foreign = "osx-arm64";
    using var tmp = new TempDirectory();
    string project = Directory.CreateDirectory(tmp.File("probe")).FullName;
    string feed = tmp.File("feed");
    // A small tool with grcis's packaging settings, using the library as grcis does (its ReadyToRun compile is the
    // one a platform package makes of it).
    string references = string.Concat(new[] { "GrCis.Rendering", "GrCis.Mathematics", "StbImageSharp" }.Select(a =>
      $"    <Reference Include=\"{Path.Combine(AppContext.BaseDirectory, a + ".dll")}\" />\n"));
    File.WriteAllText(Path.Combine(project, "Probe.csproj"), $"""
      <Project Sdk="Microsoft.NET.Sdk">
        <Import Project="{ToolProps}" />
        <PropertyGroup>
          <OutputType>Exe</OutputType>
          <TargetFramework>net10.0</TargetFramework>
          <AssemblyName>grcis</AssemblyName>
          <PackageId>GrCis.Cli.Probe</PackageId>
          <PackAsTool>true</PackAsTool>
          <ToolCommandName>grcis</ToolCommandName>
          <InvariantGlobalization>true</InvariantGlobalization>
        </PropertyGroup>
        <ItemGroup>
      {references}
        </ItemGroup>
        <ItemGroup>
          <RuntimeHostConfigurationOption Include="System.Runtime.TieredCompilation.CallCountingDelayMs" Value="10" />
        </ItemGroup>
      </Project>
      """);
    File.WriteAllText(Path.Combine(project, "Program.cs"), "System.Console.WriteLine(new Rendering.CheckerTexture(1, 1, new double[] { 1, 1, 1 }).Fu);\n");

    (int code, string output) = Dotnet(project, "pack", "-c", "Release", "-o", feed, $"-p:GrCisToolRids={Foreign}", "--disable-build-servers");
    Assert.True(code == 0, $"pack for {Foreign} failed:\n" + output);

    Assert.Equal(new[] { Foreign }, ToolPackageCheck.PlatformsOfPointer(Path.Combine(feed, "GrCis.Cli.Probe.1.0.0.nupkg")));
    ToolPackageCheck.PlatformPackage(Path.Combine(feed, $"GrCis.Cli.Probe.{Foreign}.1.0.0.nupkg"), Foreign, "grcis", "grcis.dll", "GrCis.Rendering.dll");
  }

  [Fact]
  public void ReadyToRun_machine_of_this_platform_is_the_runtimes_own()
  {
    // The runtime's own library is compiled ahead of time for this machine.
    using var pe = new System.Reflection.PortableExecutable.PEReader(File.OpenRead(typeof(object).Assembly.Location));
    string rid = System.Runtime.InteropServices.RuntimeInformation.RuntimeIdentifier;
    Assert.Equal(ToolPackageCheck.ReadyToRunMachine(rid), (ushort)pe.PEHeaders.CoffHeader.Machine);
    // Each release platform's mark differs from every other's.
    string[] rids = ReleaseRids().Where(r => r != "any").ToArray();
    Assert.Equal(rids.Length, rids.Select(ToolPackageCheck.ReadyToRunMachine).Distinct().Count());
  }

  [Fact]
  public void ReadyToRun_options_are_told_by_the_image()
  {
    // The runtime's own libraries are per-assembly images: no other assembly's code inlined or held.
    foreach (Type t in new[] { typeof(object), typeof(System.Collections.Generic.LinkedList<int>), typeof(System.Text.Json.JsonDocument) })
    {
      using var pe = new System.Reflection.PortableExecutable.PEReader(File.OpenRead(t.Assembly.Location));
      var traits = ToolPackageCheck.ReadyToRunTraits(pe);
      Assert.NotNull(traits);
      Assert.False(traits.Value.InlinesOtherAssemblies, t.Assembly.GetName().Name);
      Assert.Equal(0u, traits.Value.Flags & ToolPackageCheck.HoldsOtherAssemblysGenerics);
      // Microsoft compiles them with the profiles of its own training, embedded.
      Assert.True(traits.Value.EmbedsProfile, t.Assembly.GetName().Name);
      Assert.Throws<Xunit.Sdk.TrueException>(() => ToolPackageCheck.CompiledAcrossAssemblies(pe, t.Assembly.GetName().Name!));
    }
    using var plain = new System.Reflection.PortableExecutable.PEReader(File.OpenRead(typeof(ReleasePackagesTests).Assembly.Location));
    Assert.Null(ToolPackageCheck.ReadyToRunTraits(plain));
  }

  [Fact]
  public void Launchers_are_told_by_their_headers()
  {
    // This process's launcher (dotnet or the test host's apphost) is for this platform.
    Assert.Equal(System.Runtime.InteropServices.RuntimeInformation.RuntimeIdentifier, ToolPackageCheck.Launcher(File.ReadAllBytes(Environment.ProcessPath!)));
    Assert.Equal("unknown", ToolPackageCheck.Launcher(new byte[64]));
  }

  /// <summary>
  /// The maintainer's check of a release: <c>GRCIS_RELEASE_ARTIFACTS</c> names the folder the release pack wrote
  /// (skipped without it). The pointer names every platform; each platform's package holds its launcher, grcis's
  /// runtime settings, and grcis, the library and Roslyn compiled for it; the portable package holds plain code.
  /// </summary>
  [SkippableFact]
  public void Release_artifacts_hold_every_platforms_ReadyToRun_tool()
  {
    string? artifacts = Environment.GetEnvironmentVariable("GRCIS_RELEASE_ARTIFACTS");
    Skip.If(string.IsNullOrEmpty(artifacts), "GRCIS_RELEASE_ARTIFACTS names no release pack (docs/performance.md, \"The release packages\")");
    string version = Scaffolding.SceneFolderTemplate.PackageVersion;
    string[] rids = ReleaseRids();
    Assert.Equal(rids.OrderBy(r => r), ToolPackageCheck.PlatformsOfPointer(Path.Combine(artifacts, $"GrCis.Cli.{version}.nupkg")).OrderBy(r => r));
    foreach (string rid in rids.Where(r => r != "any"))
      ToolPackageCheck.PlatformPackage(Path.Combine(artifacts, $"GrCis.Cli.{rid}.{version}.nupkg"), rid, "grcis",
                                       "grcis.dll", "GrCis.Rendering.dll", "GrCis.Hosting.dll", "GrCis.Scripting.dll", "Microsoft.CodeAnalysis.CSharp.dll");
    ToolPackageCheck.PortablePackage(Path.Combine(artifacts, $"GrCis.Cli.any.{version}.nupkg"), "grcis");
  }

  /// <summary>Runs dotnet in <paramref name="folder"/> to its end (at most 3 minutes): exit code and output.</summary>
  static (int Code, string Output) Dotnet(string folder, params string[] args)
  {
    // The test host's MSBuild settings are not the child's; no build servers left running.
    var env = new Dictionary<string, string?>();
    foreach (DictionaryEntry e in Environment.GetEnvironmentVariables())
      if (((string)e.Key).StartsWith("MSBUILD", StringComparison.OrdinalIgnoreCase))
        env[(string)e.Key] = null;
    env["MSBUILDDISABLENODEREUSE"] = "1";
    env["DOTNET_CLI_USE_MSBUILD_SERVER"] = "0";
    env["UseSharedCompilation"] = "false";
    // Minutes to spare: on a fresh NuGet folder the release restore downloads about 250 MB of runtime packs first.
    return Shell.Run(folder, env, TimeSpan.FromMinutes(10), PackagesTests.Dotnet, args);
  }
}
