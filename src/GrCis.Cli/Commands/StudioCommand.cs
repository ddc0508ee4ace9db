using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Diagnostics;
using System.IO;
using GrCis.Studio;

namespace GrCis.Cli.Commands;

/// <summary>
/// <c>grcis studio [SCRIPT.cs | DIR]... [--port N] [--host ADDR] [--no-open] [--nodefault]</c>: the
/// interactive demo as a local web page. Prints one line with the URL (token included) on stdout, opens
/// the default browser unless <c>--no-open</c>, and serves until Ctrl+C (exit 130).
/// </summary>
public sealed class StudioCommand
{
  readonly Argument<string[]> paths = new("paths")
  {
    Description = "Scene scripts (*.cs) and folders of scripts to list; the studio reads and writes no other files",
    Arity = ArgumentArity.ZeroOrMore,
  };

  readonly Option<int> port = new("--port") { Description = "Port to listen on; 0 = a free one", DefaultValueFactory = _ => 0 };

  readonly Option<string> host = new("--host")
  {
    Description = "Address to bind (default 127.0.0.1: this machine only; reach it from elsewhere with ssh -L)",
    DefaultValueFactory = _ => "127.0.0.1",
  };

  readonly Option<bool> noOpen = new("--no-open") { Description = "Do not open a browser" };

  readonly Option<bool> noDefault = new("--nodefault", "-nodefault") { Description = "Leave the built-in scenes out of the list" };

  public Command Build(CliEnvironment env)
  {
    var cmd = new Command("studio", "The interactive demo in the browser: render, preview, probe pixels") { paths, port, host, noOpen, noDefault };
    cmd.SetAction(parse => Execute(parse, env));
    return cmd;
  }

  int Execute(ParseResult parse, CliEnvironment env)
  {
    int p = parse.GetValue(port);
    if (p is < 0 or > 65535)
      throw new UsageException($"invalid --port {p}: 0 to 65535");
    string address = parse.GetValue(host)!;
    if (address != "localhost" && !System.Net.IPAddress.TryParse(address.Trim('[', ']'), out _))
      throw new UsageException($"invalid --host '{address}': an IP address such as 127.0.0.1, or localhost");
    var options = new StudioOptions
    {
      Host = address,
      Port = p,
      Paths = parse.GetValue(paths) ?? Array.Empty<string>(),
      NoDefault = parse.GetValue(noDefault),
      ScriptCache = env.ScriptCache,
      WarmEditor = true,
    };
    foreach (string path in options.Paths)
      if (!File.Exists(path) && !Directory.Exists(path))
        throw new UsageException($"'{path}' is not a scene script or a folder");
    if (!options.IsLoopback)
      env.Error.WriteLine($"grcis: warning: --host {address} lets other machines reach the studio; anyone with the token can run code as you");

    var problems = new List<string>();
    StudioServer server;
    try
    {
      server = StudioServer.StartAsync(options, problems, env.Cancel).GetAwaiter().GetResult();
    }
    catch (IOException e)
    {
      throw new CliFailure($"cannot listen on {address}:{p}: {e.Message}");
    }
    try
    {
      foreach (string problem in problems)
        env.Error.WriteLine("grcis: note: " + problem);
      env.Out.WriteLine(server.Url);
      env.Out.Flush();
      if (!parse.GetValue(noOpen))
        OpenBrowser(server.Url, env);
      server.WaitAsync(env.Cancel).GetAwaiter().GetResult();
    }
    finally
    {
      server.DisposeAsync().AsTask().GetAwaiter().GetResult();
    }
    return ExitCodes.Cancelled;
  }

  static void OpenBrowser(string url, CliEnvironment env)
  {
    try
    {
      if (OperatingSystem.IsLinux())
        Process.Start(new ProcessStartInfo("xdg-open", url) { UseShellExecute = false })?.Dispose();
      else
        Process.Start(new ProcessStartInfo(url) { UseShellExecute = true })?.Dispose();
    }
    catch (Exception e) when (e is System.ComponentModel.Win32Exception or InvalidOperationException)
    {
      env.Error.WriteLine("grcis: note: no browser could be opened; open the URL above yourself");
    }
  }
}
