using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using System.Threading.Tasks;

namespace GrCis.StaticPgo;

/// <summary>
/// The build the training runs: a copy of the JIT-compiled grcis whose own assemblies are compiled ahead of time for
/// this machine, as the shipped build is. The runtime profiles a hot precompiled method in an optimized, instrumented
/// tier; a JIT-compiled method with a loop it cannot leave mid-way (one with <c>stackalloc</c>, as the Whitted kernel's
/// <c>Shade</c>) is compiled optimized at its first call instead and never counted, so JIT-only training missed it.
/// </summary>
internal static class TrainingBuild
{
  /// <summary>Copies <paramref name="appFolder"/> to <paramref name="target"/> and compiles <paramref name="assemblies"/> there.</summary>
  public static string Prepare(string crossgen, string appFolder, IReadOnlyList<string> assemblies, string target, TextWriter log)
  {
    if (Directory.Exists(target)) Directory.Delete(target, recursive: true);
    Directory.CreateDirectory(target);
    foreach (string file in Directory.GetFiles(appFolder, "*", SearchOption.AllDirectories))
    {
      string copy = Path.Combine(target, Path.GetRelativePath(appFolder, file));
      Directory.CreateDirectory(Path.GetDirectoryName(copy)!);
      File.Copy(file, copy);
    }

    string[] references = [Path.Combine(appFolder, "*.dll"), .. FrameworkFolders().Select(f => Path.Combine(f, "*.dll"))];
    string os = OperatingSystem.IsWindows() ? "windows" : OperatingSystem.IsMacOS() ? "osx" : "linux";
    string arch = RuntimeInformation.OSArchitecture.ToString().ToLowerInvariant();
    var clock = Stopwatch.StartNew();
    Parallel.ForEach(assemblies, new ParallelOptions { MaxDegreeOfParallelism = Environment.ProcessorCount }, assembly =>
    {
      var start = new ProcessStartInfo(crossgen);
      start.ArgumentList.Add(assembly);
      start.ArgumentList.Add("-o");
      start.ArgumentList.Add(Path.Combine(target, Path.GetFileName(assembly)));
      foreach (string r in references) start.ArgumentList.Add("-r:" + r);
      start.ArgumentList.Add("--targetos:" + os);
      start.ArgumentList.Add("--targetarch:" + arch);
      start.ArgumentList.Add("-O");
      ChildProcess.Run(start, $"the ReadyToRun compiler on {assembly}");
    });
    log.WriteLine($"training build: {assemblies.Count} assemblies compiled ahead of time ({clock.Elapsed.TotalSeconds:0.0} s)");
    return Path.Combine(target, "grcis.dll");
  }

  /// <summary>The shared frameworks of the runtime this tool runs on (.NET's own and ASP.NET Core's, newest).</summary>
  static IEnumerable<string> FrameworkFolders()
  {
    string core = RuntimeEnvironment.GetRuntimeDirectory().TrimEnd(Path.DirectorySeparatorChar);
    yield return core;
    string web = Path.Combine(Path.GetDirectoryName(Path.GetDirectoryName(core)!)!, "Microsoft.AspNetCore.App");
    if (Directory.Exists(web)
        && Directory.GetDirectories(web).Select(d => (Path: d, Version: Version.TryParse(Path.GetFileName(d).Split('-')[0], out Version? v) ? v : null))
             .Where(d => d.Version != null).OrderByDescending(d => d.Version).FirstOrDefault() is { Path: { } newest })
      yield return newest;
  }
}
