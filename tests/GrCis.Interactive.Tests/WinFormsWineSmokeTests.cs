using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using GrCis.TestSupport;

namespace GrCis.Interactive.Tests;

/// <summary>
/// The WinForms demo window itself (demos/GrCis.Demo.WinForms), published for win-x64 and started under
/// Wine on a virtual X display: <c>-render-to</c> drives the window's own Render and Save image path,
/// and the saved PNG must equal <c>grcis render</c>'s byte for byte, for five kinds of script: plain (Five balls),
/// animated (Orbit, whose moving ball the window once lost), textured (an image texture), distributed ray
/// tracing (depth of field) and path-traced (the Cornell box). Needs the Debian packages wine and
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
  public void Demo_window_under_wine_renders_five_kinds_of_script_like_grcis_render()
  {
    RequiredTool.Find("wine", "wine");
    string xvfbRun = RequiredTool.Find("xvfb-run", "xvfb");
    string root = RepoRoot();
    using var tmp = new TempDir();

    var (code, log) = Run(Dotnet, ["publish", Path.Combine(root, "demos", "GrCis.Demo.WinForms"), "-c", "Release", "-r", "win-x64",
      "--self-contained", "-o", tmp.File("demo"), "-nologo"], null, TimeSpan.FromMinutes(5));
    Assert.True(code == 0, "publishing the demo failed: " + log);

    var env = new Dictionary<string, string>
    {
      ["WINEPREFIX"] = tmp.File("wine-prefix"),
      ["WINEDEBUG"] = "-all",
      // The CLR under Wine 8 needs W^X off (docs/interactive.md).
      ["DOTNET_EnableWriteXorExecute"] = "0",
    };
    foreach (string name in new[] { "FiveBalls", "Orbit", "ImageTexture", "DepthOfField", "CornellBox" })
    {
      string script = Path.Combine(root, "scripts", name + ".cs");
      string window = tmp.File(name + "-window.png"), cli = tmp.File(name + "-cli.png");
      (code, log) = Run(xvfbRun, ["-a", "-s", "-screen 0 1280x900x24", "wine", tmp.File("demo/grcis-demo.exe"),
        "-nodefault", "-scene", script, "-render-to", window], env, TimeSpan.FromMinutes(6));
      Assert.True(File.Exists(window), $"the window saved no image of {name} (exit {code}): {log}");

      var error = new StringWriter();
      Assert.True(GrCis.Cli.Program.Run(["render", script, "-o", cli, "-q"], new StringWriter(), error) == 0, error.ToString());
      Assert.True(File.ReadAllBytes(cli).AsSpan().SequenceEqual(File.ReadAllBytes(window)), $"{name}: the window's PNG differs from grcis render's");
    }
  }
}
