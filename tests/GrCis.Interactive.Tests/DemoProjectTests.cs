using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;

namespace GrCis.Interactive.Tests;

/// <summary>
/// The demo's project file finds the WinForms runtime pack however the package folder is spelled: NuGet takes
/// <c>NUGET_PACKAGES</c> as given, so <c>$(NuGetPackageRoot)</c> may lack its trailing slash (and
/// <c>…/packagesmicrosoft.windowsdesktop…</c> failed the demo's build, MSB3106).
/// </summary>
public class DemoProjectTests
{
  static string RepoRoot()
  {
    for (DirectoryInfo? d = new(AppContext.BaseDirectory); d != null; d = d.Parent)
      if (File.Exists(Path.Combine(d.FullName, "GrCis.sln")) && Directory.Exists(Path.Combine(d.FullName, "demos")))
        return d.FullName;
    throw new InvalidOperationException("repository root not found above " + AppContext.BaseDirectory);
  }

  static string Dotnet => Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") is { Length: > 0 } host ? host : "dotnet";

  [Fact]
  public void WinForms_runtime_pack_path_has_a_slash_after_a_package_root_without_one()
  {
    using var tmp = new TempDir();
    string packages = tmp.File("packages"); // no trailing slash, as NUGET_PACKAGES is often set
    string project = Path.Combine(RepoRoot(), "demos", "GrCis.Demo.WinForms", "GrCis.Demo.WinForms.csproj");

    var psi = new ProcessStartInfo(Dotnet) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
    foreach (string a in new[] { "msbuild", project, "-nologo", "-getProperty:WindowsDesktopLib", "-p:WinFormsFromRuntimePack=true",
                                 "-p:NuGetPackageRoot=" + packages, "-p:RuntimeIdentifier=win-x64", "-p:WindowsDesktopRuntimeVersion=10.0.0" })
      psi.ArgumentList.Add(a);
    psi.Environment["NUGET_PACKAGES"] = packages;
    foreach (string k in Environment.GetEnvironmentVariables().Keys.Cast<string>().Where(k => k.StartsWith("MSBUILD", StringComparison.OrdinalIgnoreCase)).ToList())
      psi.Environment.Remove(k);
    using Process p = Process.Start(psi)!;
    var stderr = p.StandardError.ReadToEndAsync();
    string stdout = p.StandardOutput.ReadToEnd();
    Assert.True(p.WaitForExit(120_000), "dotnet msbuild -getProperty did not finish in 2 minutes");
    Assert.True(p.ExitCode == 0, stdout + stderr.Result);

    Assert.Equal(packages + "/microsoft.windowsdesktop.app.runtime.win-x64/10.0.0/runtimes/win-x64/lib/net10.0/",
                 stdout.Trim().Replace('\\', '/'));
  }

  public static IEnumerable<object[]> BuildFiles() =>
    Directory.EnumerateFiles(RepoRoot(), "*.*", SearchOption.AllDirectories)
      .Where(f => f.EndsWith("proj", StringComparison.Ordinal) || f.EndsWith(".props", StringComparison.Ordinal) || f.EndsWith(".targets", StringComparison.Ordinal))
      .Where(f => !f.Contains("/obj/", StringComparison.Ordinal) && !f.Contains("/bin/", StringComparison.Ordinal) && !f.Contains("/.git/", StringComparison.Ordinal))
      .Select(f => new object[] { Path.GetRelativePath(RepoRoot(), f) });

  [Theory]
  [MemberData(nameof(BuildFiles))]
  public void Every_path_built_on_the_package_root_ensures_its_slash(string file)
  {
    string text = File.ReadAllText(Path.Combine(RepoRoot(), file));
    foreach (Match m in Regex.Matches(text, @"\$\(NuGetPackageRoot\)"))
    {
      string before = text[Math.Max(0, m.Index - 30)..m.Index];
      Assert.True(before.EndsWith("EnsureTrailingSlash(", StringComparison.Ordinal),
        $"{file}: $(NuGetPackageRoot) used without $([MSBuild]::EnsureTrailingSlash(...)) (NUGET_PACKAGES may lack the slash)");
    }
  }
}
