using System;
using System.Collections;
using System.Collections.Generic;
using System.IO;
using System.IO.Compression;
using System.Linq;
using System.Text;
using GrCis.Cli.Scaffolding;

namespace GrCis.Cli.Tests;

/// <summary>
/// The packages as a user meets them (README, "Install as a .NET tool"): packed into a folder feed, the grcis
/// tool and the scene template installed into a fresh home, <c>dotnet new grcis-scene</c>, <c>dotnet build</c>
/// (which also catches an error in the script), <c>dotnet run</c> (a quick render of the scene) and the installed
/// <c>grcis render Scene.cs</c>.
/// </summary>
[Collection(RepositoryPacking.Name)]
public class PackagesTests
{
#if DEBUG
  const string Configuration = "Debug";
#else
  const string Configuration = "Release";
#endif

  internal static string Dotnet => Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") is { Length: > 0 } host ? host : "dotnet";

  [Fact]
  public void Packed_tool_and_template_make_a_scene_folder_that_builds_and_renders()
  {
    using var tmp = new TempDirectory();
    string feed = Directory.CreateDirectory(tmp.File("artifacts")).FullName;
    string home = Directory.CreateDirectory(tmp.File("home")).FullName;
    string work = Directory.CreateDirectory(tmp.File("work")).FullName;
    string version = SceneFolderTemplate.PackageVersion;

    // Pack what the test run has just built (the library, the tool), and the template (nothing to compile).
    // The tool as its one portable package (the platform packages compiled ahead of time are README's, ReadmeTests).
    foreach (string project in new[] { "src/GrCis.Mathematics", "src/GrCis.Rendering", "src/GrCis.Compatibility", "src/GrCis.Cli" })
      Run(RepoPaths.Root, null, "pack", project, "-c", Configuration, "--no-build", "-o", feed, "--disable-build-servers", "-p:GrCisToolRids=portable");
    Run(RepoPaths.Root, null, "pack", "templates/GrCis.Templates.csproj", "-c", Configuration, "-o", feed, "--disable-build-servers");
    foreach (string id in new[] { "GrCis.Mathematics", "GrCis.Rendering", "GrCis.Compatibility", "GrCis.Cli", "GrCis.Templates" })
      Assert.True(File.Exists(Path.Combine(feed, $"{id}.{version}.nupkg")), $"{id}.{version}.nupkg not packed");
    // The library brings its doc comments (IDE hover) and its PDB (stepping in, source link).
    foreach (string id in new[] { "GrCis.Mathematics", "GrCis.Rendering" })
      using (ZipArchive library = ZipFile.OpenRead(Path.Combine(feed, $"{id}.{version}.nupkg")))
        foreach (string part in new[] { ".dll", ".xml", ".pdb" })
          Assert.Contains(library.Entries, e => e.FullName == $"lib/net10.0/{id}{part}");
    // The library's package brings the math's (OpenTK.Mathematics), of the same version; the math's brings no generator.
    using (ZipArchive library = ZipFile.OpenRead(Path.Combine(feed, $"GrCis.Rendering.{version}.nupkg")))
    using (var nuspec = new StreamReader(library.GetEntry("GrCis.Rendering.nuspec")!.Open()))
      Assert.Contains($"<dependency id=\"GrCis.Mathematics\" version=\"{version}\"", nuspec.ReadToEnd(), StringComparison.Ordinal);
    using (ZipArchive math = ZipFile.OpenRead(Path.Combine(feed, $"GrCis.Mathematics.{version}.nupkg")))
    {
      Assert.DoesNotContain(math.Entries, e => e.FullName.Contains("Generators", StringComparison.Ordinal));
      using var nuspec = new StreamReader(math.GetEntry("GrCis.Mathematics.nuspec")!.Open());
      Assert.DoesNotContain("<dependency ", nuspec.ReadToEnd(), StringComparison.Ordinal);
    }

    // The local feed first, then the sources this machine restores from (for StbImageSharp): the fresh home has none.
    WriteNuGetConfig(work, feed);
    Dictionary<string, string?> env = FreshHome(home);

    Run(work, env, "tool", "install", "--global", "--add-source", feed, "GrCis.Cli");
    // The installed tool keeps grcis's runtime settings (hot methods optimised at once).
    string[] configs = Directory.GetFiles(Path.Combine(home, ".dotnet", "tools", ".store"), "grcis.runtimeconfig.json", SearchOption.AllDirectories);
    Assert.Equal(ExecutableTests.CallCountingDelayMs(Path.Combine(AppContext.BaseDirectory, "grcis.runtimeconfig.json")),
                 ExecutableTests.CallCountingDelayMs(Assert.Single(configs)));
    Run(work, env, "new", "install", Path.Combine(feed, $"GrCis.Templates.{version}.nupkg"));
    Run(work, env, "new", "grcis-scene", "-o", "MyScene");
    string folder = Path.Combine(work, "MyScene");
    Assert.True(File.Exists(Path.Combine(folder, "MyScene.csproj")));
    Run(folder, env, "build", "-tl:off", "-v", "q", "--disable-build-servers");

    // The installed tool renders the script as the in-process CLI renders the template's own.
    string grcis = Path.Combine(home, ".dotnet", "tools", OperatingSystem.IsWindows() ? "grcis.exe" : "grcis");
    (int code, string output) = Exec(folder, env, grcis, "render", "Scene.cs", "--size", "96x72", "-o", "scene.png", "-q");
    Assert.True(code == 0, "grcis render: " + output);
    CliRun expected = CliRun.Of(tmp.Path, "render", Path.Combine(RepoPaths.Root, "templates", "grcis-scene", "Scene.cs"), "--size", "96x72", "-o", "expected.png", "-q");
    Assert.True(expected.ExitCode == 0, expected.Error);
    Assert.Equal(File.ReadAllBytes(tmp.File("expected.png")), File.ReadAllBytes(Path.Combine(folder, "scene.png")));

    // dotnet run (students try it) runs the script as a program and renders its scene: the PNG grcis render writes
    // of the template's script at grcis's default size, exit 0.
    (int runCode, string runOutput) = Exec(folder, env, Dotnet, "run", "--no-build");
    Assert.True(runCode == 0, "dotnet run: " + runOutput);
    Assert.Contains("grcis render Scene.cs", runOutput, StringComparison.Ordinal);
    CliRun expected640 = CliRun.Of(tmp.Path, "render", Path.Combine(RepoPaths.Root, "templates", "grcis-scene", "Scene.cs"), "-o", "expected640.png", "-q");
    Assert.True(expected640.ExitCode == 0, expected640.Error);
    Assert.Equal(File.ReadAllBytes(tmp.File("expected640.png")), File.ReadAllBytes(Path.Combine(folder, "scene.png")));
    // With a parameter from its command line, as grcis render --param gives it.
    (runCode, runOutput) = Exec(folder, env, Dotnet, "run", "--no-build", "--", "radius=0.5");
    Assert.True(runCode == 0, "dotnet run -- radius=0.5: " + runOutput);
    Assert.NotEqual(File.ReadAllBytes(tmp.File("expected640.png")), File.ReadAllBytes(Path.Combine(folder, "scene.png")));

    // dotnet build reports a type error in the script at its line.
    int lines = File.ReadAllLines(Path.Combine(folder, "Scene.cs")).Length;
    File.AppendAllText(Path.Combine(folder, "Scene.cs"), "scene.BackgroundColor = \"dark\";\n");
    (int buildCode, string buildOutput) = Exec(folder, env, Dotnet, "build", "-tl:off", "-v", "q", "--disable-build-servers");
    Assert.NotEqual(0, buildCode);
    Assert.Contains($"Scene.cs({lines + 1},", buildOutput, StringComparison.Ordinal);
    Assert.Contains("CS0029", buildOutput, StringComparison.Ordinal);
  }

  internal static void WriteNuGetConfig(string folder, string feed) =>
    File.WriteAllText(Path.Combine(folder, "nuget.config"), NuGetConfig(feed));

  /// <summary>A NuGet.Config with <paramref name="feed"/> (if any) first, then the enabled sources this machine restores from.</summary>
  internal static string NuGetConfig(string? feed)
  {
    (int code, string sources) = Exec(Path.GetTempPath(), null, Dotnet, "nuget", "list", "source", "--format", "short");
    Assert.True(code == 0, sources);
    var config = new StringBuilder("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<configuration>\n  <packageSources>\n");
    if (feed != null)
      config.Append($"    <add key=\"grcis-local\" value=\"{feed}\" />\n");
    int n = 0;
    foreach (string line in sources.Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries))
      if (line.StartsWith("E ", StringComparison.Ordinal))
        config.Append($"    <add key=\"machine-{n++}\" value=\"{System.Security.SecurityElement.Escape(line[2..].Trim())}\" />\n");
    config.Append("  </packageSources>\n</configuration>\n");
    return config.ToString();
  }

  /// <summary>The environment with home, .NET's and NuGet's folders in <paramref name="home"/>: nothing is installed for the user.</summary>
  internal static Dictionary<string, string?> FreshHome(string home)
  {
    var env = new Dictionary<string, string?>
    {
      ["HOME"] = home,
      ["USERPROFILE"] = home,
      ["DOTNET_CLI_HOME"] = home,
      ["NUGET_PACKAGES"] = Path.Combine(home, "nuget-packages"),
      ["NUGET_HTTP_CACHE_PATH"] = Path.Combine(home, "nuget-http-cache"),
      ["XDG_DATA_HOME"] = Path.Combine(home, ".local", "share"),
      ["XDG_CONFIG_HOME"] = Path.Combine(home, ".config"),
      ["XDG_CACHE_HOME"] = Path.Combine(home, ".cache"),
      ["LOCALAPPDATA"] = Path.Combine(home, "AppData", "Local"),
      ["APPDATA"] = Path.Combine(home, "AppData", "Roaming"),
      ["DOTNET_NOLOGO"] = "1",
      ["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1",
      ["DOTNET_SKIP_FIRST_TIME_EXPERIENCE"] = "1",
      ["DOTNET_GENERATE_ASPNET_CERTIFICATE"] = "false",
      ["DOTNET_ADD_GLOBAL_TOOLS_TO_PATH"] = "false",
    };
    // The installed tool's launcher finds the runtime beside the dotnet that runs the tests.
    if (Path.IsPathRooted(Dotnet))
      env["DOTNET_ROOT"] = Path.GetDirectoryName(Dotnet);
    // The test host's MSBuild settings are not the child's.
    foreach (DictionaryEntry e in Environment.GetEnvironmentVariables())
      if (((string)e.Key).StartsWith("MSBUILD", StringComparison.OrdinalIgnoreCase))
        env[(string)e.Key] = null;
    return env;
  }

  static void Run(string folder, Dictionary<string, string?>? env, params string[] args)
  {
    (int code, string output) = Exec(folder, env, Dotnet, args);
    Assert.True(code == 0, $"dotnet {string.Join(' ', args)} failed ({code}):\n{output}");
  }

  /// <summary>Runs a program to its end (at most 3 minutes); exit code and stdout + stderr.</summary>
  internal static (int Code, string Output) Exec(string folder, Dictionary<string, string?>? env, string program, params string[] args) =>
    Shell.Run(folder, env, TimeSpan.FromMinutes(3), program, args);
}
