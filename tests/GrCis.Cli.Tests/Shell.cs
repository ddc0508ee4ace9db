using System;
using System.Collections.Generic;
using System.Diagnostics;

namespace GrCis.Cli.Tests;

/// <summary>Runs a program to its end with stdout and stderr captured together.</summary>
internal static class Shell
{
  public static (int Code, string Output) Run(string folder, IDictionary<string, string?>? env, TimeSpan limit, string program, params string[] args)
  {
    var psi = new ProcessStartInfo(program)
    {
      WorkingDirectory = folder,
      RedirectStandardOutput = true,
      RedirectStandardError = true,
      RedirectStandardInput = true,
      UseShellExecute = false,
    };
    foreach (string a in args)
      psi.ArgumentList.Add(a);
    if (env != null)
    {
      foreach ((string k, string? v) in env)
      {
        if (v == null)
          psi.Environment.Remove(k);
        else
          psi.Environment[k] = v;
      }
    }
    using Process p = Process.Start(psi)!;
    p.StandardInput.Close();
    var stdout = p.StandardOutput.ReadToEndAsync();
    var stderr = p.StandardError.ReadToEndAsync();
    if (!p.WaitForExit(limit))
    {
      p.Kill(entireProcessTree: true);
      Assert.Fail($"{program} {string.Join(' ', args)} did not finish in {limit.TotalMinutes} minutes");
    }
    p.WaitForExit();
    return (p.ExitCode, stdout.Result + stderr.Result);
  }
}
