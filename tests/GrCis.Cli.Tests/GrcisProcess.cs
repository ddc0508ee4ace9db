using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;

namespace GrCis.Cli.Tests;

/// <summary>The built <c>grcis</c> as a real process (<c>dotnet exec grcis.dll …</c>).</summary>
internal static class GrcisProcess
{
  public static string Dll
  {
    get
    {
      string dll = Path.Combine(AppContext.BaseDirectory, "grcis.dll");
      Assert.True(File.Exists(dll), $"built CLI not found at {dll}");
      return dll;
    }
  }

  public static string Dotnet => Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") is { Length: > 0 } host ? host : "dotnet";

  /// <summary>Starts <c>grcis</c> with its output captured (read it with <see cref="Finish"/>).</summary>
  public static Process Start(string workingDirectory, IDictionary<string, string>? env, params string[] args)
  {
    var psi = new ProcessStartInfo(Dotnet)
    {
      WorkingDirectory = workingDirectory,
      RedirectStandardOutput = true,
      RedirectStandardError = true,
      UseShellExecute = false,
    };
    psi.ArgumentList.Add("exec");
    psi.ArgumentList.Add(Dll);
    foreach (string a in args)
      psi.ArgumentList.Add(a);
    if (env != null)
      foreach (var (k, v) in env)
        psi.Environment[k] = v;
    return Process.Start(psi)!;
  }

  /// <summary>Waits (at most 3 minutes) and returns exit code and output.</summary>
  public static (int Code, string Out, string Error) Finish(Process p)
  {
    var stdout = p.StandardOutput.ReadToEndAsync();
    var stderr = p.StandardError.ReadToEndAsync();
    if (!p.WaitForExit(180_000))
    {
      p.Kill(entireProcessTree: true);
      Assert.Fail("grcis did not finish in 3 minutes");
    }
    return (p.ExitCode, stdout.Result, stderr.Result);
  }

  public static (int Code, string Out, string Error) Run(string workingDirectory, params string[] args)
  {
    using Process p = Start(workingDirectory, null, args);
    return Finish(p);
  }

  public static (int Code, string Out, string Error) Run(string workingDirectory, IDictionary<string, string> env, params string[] args)
  {
    using Process p = Start(workingDirectory, env, args);
    return Finish(p);
  }

  /// <summary>
  /// Runs <c>parallel --will-cite --halt now,fail=1 -j N dotnet exec grcis.dll ARGS ::: 0 … N−1</c>
  /// (the recipes of docs/scale-out.md, with <c>{}</c> in <paramref name="args"/> standing for the index).
  /// </summary>
  public static (int Code, string Out, string Error) RunParallel(string parallel, string workingDirectory, int jobs, params string[] args)
  {
    var psi = new ProcessStartInfo(parallel)
    {
      WorkingDirectory = workingDirectory,
      RedirectStandardOutput = true,
      RedirectStandardError = true,
      RedirectStandardInput = true,
      UseShellExecute = false,
    };
    foreach (string a in new[] { "--will-cite", "--halt", "now,fail=1", "-j", jobs.ToString(), Dotnet, "exec", Dll })
      psi.ArgumentList.Add(a);
    foreach (string a in args)
      psi.ArgumentList.Add(a);
    psi.ArgumentList.Add(":::");
    for (int i = 0; i < jobs; i++)
      psi.ArgumentList.Add(i.ToString());
    using Process p = Process.Start(psi)!;
    p.StandardInput.Close();
    return Finish(p);
  }
}
