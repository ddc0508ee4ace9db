using System;
using System.Diagnostics;
using System.IO;
using System.Text.Json.Nodes;
using Rendering.Imaging;

namespace GrCis.Cli.Tests;

/// <summary>Runs the built <c>grcis</c> as a real process (<c>dotnet exec grcis.dll</c>): exit codes, streams, files.</summary>
public class ExecutableTests
{
  static (int code, string stdout, string stderr) Exec(string workingDirectory, params string[] args)
  {
    string dll = Path.Combine(AppContext.BaseDirectory, "grcis.dll");
    Assert.True(File.Exists(dll), $"built CLI not found at {dll}");
    string dotnet = Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") is { Length: > 0 } host ? host : "dotnet";
    var psi = new ProcessStartInfo(dotnet)
    {
      WorkingDirectory = workingDirectory,
      RedirectStandardOutput = true,
      RedirectStandardError = true,
      UseShellExecute = false,
    };
    psi.ArgumentList.Add("exec");
    psi.ArgumentList.Add(dll);
    foreach (string a in args)
      psi.ArgumentList.Add(a);
    using Process p = Process.Start(psi)!;
    var stdout = p.StandardOutput.ReadToEndAsync();
    string stderr = p.StandardError.ReadToEnd();
    Assert.True(p.WaitForExit(120_000), "grcis did not finish in 2 minutes");
    return (p.ExitCode, stdout.Result, stderr);
  }

  [Fact]
  public void Process_renders_default_scene_and_exits_zero()
  {
    using var dir = new TempDirectory();
    var (code, stdout, stderr) = Exec(dir.Path, "render", "--size", "32x24", "-o", "proc.png");

    Assert.True(code == 0, $"exit {code}: {stderr}");
    Assert.StartsWith("wrote ", stdout);
    Assert.Contains("100%", stderr);
    Rgb8Image image = PngFile.Load(dir.File("proc.png"));
    Assert.Equal((32, 24), (image.Width, image.Height));
  }

  [Fact]
  public void Process_reports_bad_size_with_exit_two_and_writes_nothing()
  {
    using var dir = new TempDirectory();
    var (code, stdout, stderr) = Exec(dir.Path, "render", "--size", "0x10", "-o", "bad.png");

    Assert.Equal(2, code);
    Assert.Equal("", stdout);
    Assert.Equal("grcis: error: invalid --size '0x10': width and height must be positive", stderr.Trim());
    Assert.Empty(dir.AllFiles());
  }

  [Fact]
  public void Grcis_asks_the_runtime_for_optimised_code_as_soon_as_a_method_is_hot()
  {
    // The runtime's default delay (100 ms without a newly compiled method) kept a short render in unoptimised code.
    Assert.InRange(CallCountingDelayMs(Path.Combine(AppContext.BaseDirectory, "grcis.runtimeconfig.json")) ?? 100, 0, 10);
  }

  [Fact]
  public void Grcis_starts_without_the_runtimes_managed_event_sources()
  {
    // Built at every start by reflection over their attributes, for listeners grcis never has.
    string runtimeConfig = Path.Combine(AppContext.BaseDirectory, "grcis.runtimeconfig.json");
    JsonNode? value = RuntimeOption(JsonNode.Parse(File.ReadAllText(runtimeConfig))!, "System.Diagnostics.Tracing.EventSource.IsSupported");
    Assert.False(value?.GetValue<bool>() ?? true, $"{runtimeConfig} leaves EventSource on");
  }

  /// <summary>The tiering delay a <c>runtimeconfig.json</c> sets, or null when it leaves the runtime's default.</summary>
  internal static int? CallCountingDelayMs(string runtimeConfig)
  {
    Assert.True(File.Exists(runtimeConfig), $"{runtimeConfig} not found");
    return RuntimeOption(JsonNode.Parse(File.ReadAllText(runtimeConfig))!, "System.Runtime.TieredCompilation.CallCountingDelayMs")?.GetValue<int>();
  }

  /// <summary>A runtime setting of a parsed <c>runtimeconfig.json</c> (its configProperties), or null when it leaves the runtime's default.</summary>
  internal static JsonNode? RuntimeOption(JsonNode runtimeConfig, string name) =>
    runtimeConfig["runtimeOptions"]?["configProperties"]?[name];
}
