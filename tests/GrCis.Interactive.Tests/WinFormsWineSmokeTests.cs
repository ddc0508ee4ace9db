using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using GrCis.TestSupport;

namespace GrCis.Interactive.Tests;

/// <summary>
/// The WinForms demo window itself (demos/GrCis.Demo.WinForms), published for win-x64 and started under
/// Wine on a virtual X display: <c>-render-to</c> drives the window's own Render and Save image path,
/// and the saved PNG must equal <c>grcis render</c>'s byte for byte. Needs the Debian packages wine and
/// xvfb (skipped without them unless GRCIS_REQUIRE_TOOLS=1).
/// </summary>
public class WinFormsWineSmokeTests
{
  static string RepoRoot()
  {
    for (DirectoryInfo? d = new(AppContext.BaseDirectory); d != null; d = d.Parent)
      if (File.Exists(Path.Combine(d.FullName, "GrCis.sln")) && Directory.Exists(Path.Combine(d.FullName, "demos")))
        return d.FullName;
    throw new InvalidOperationException("repository root not found above " + AppContext.BaseDirectory);
  }

  static string Dotnet => Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") is { Length: > 0 } host ? host : "dotnet";

  static (int Code, string Output) Run(string file, IEnumerable<string> args, IDictionary<string, string>? env, TimeSpan limit)
  {
    var psi = new ProcessStartInfo(file) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
    foreach (string a in args)
      psi.ArgumentList.Add(a);
    if (env != null)
      foreach (var (k, v) in env)
        psi.Environment[k] = v;
    using Process p = Process.Start(psi)!;
    var stdout = p.StandardOutput.ReadToEndAsync();
    var stderr = p.StandardError.ReadToEndAsync();
    if (!p.WaitForExit(limit))
    {
      p.Kill(entireProcessTree: true);
      Assert.Fail($"{file} did not finish in {limit.TotalMinutes} minutes");
    }
    return (p.ExitCode, stdout.Result + stderr.Result);
  }

  [SkippableFact]
  public void Demo_window_under_wine_renders_five_balls_like_grcis_render()
  {
    RequiredTool.Find("wine", "wine");
    string xvfbRun = RequiredTool.Find("xvfb-run", "xvfb");
    string root = RepoRoot();
    using var tmp = new TempDir();

    var (code, log) = Run(Dotnet, ["publish", Path.Combine(root, "demos", "GrCis.Demo.WinForms"), "-c", "Release", "-r", "win-x64",
      "--self-contained", "-o", tmp.File("demo"), "-nologo"], null, TimeSpan.FromMinutes(5));
    Assert.True(code == 0, "publishing the demo failed: " + log);

    string script = Path.Combine(root, "scripts", "FiveBalls.cs");
    var env = new Dictionary<string, string>
    {
      ["WINEPREFIX"] = tmp.File("wine-prefix"),
      ["WINEDEBUG"] = "-all",
      // The CLR under Wine 8 needs W^X off (docs/interactive.md).
      ["DOTNET_EnableWriteXorExecute"] = "0",
    };
    (code, log) = Run(xvfbRun, ["-a", "-s", "-screen 0 1280x900x24", "wine", tmp.File("demo/grcis-demo.exe"),
      "-nodefault", "-scene", script, "-render-to", tmp.File("window.png")], env, TimeSpan.FromMinutes(5));
    Assert.True(File.Exists(tmp.File("window.png")), $"the window saved no image (exit {code}): {log}");

    var output = new StringWriter();
    var error = new StringWriter();
    Assert.True(GrCis.Cli.Program.Run(["render", script, "-o", tmp.File("cli.png"), "-q"], output, error) == 0, error.ToString());
    Assert.Equal(File.ReadAllBytes(tmp.File("cli.png")), File.ReadAllBytes(tmp.File("window.png")));
  }
}
