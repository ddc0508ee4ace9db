using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Diagnostics;
using System.IO;
using System.Threading;
using System.Threading.Tasks;
using GrCis.Studio;

namespace GrCis.Cli.Commands;

/// <summary>
/// <c>grcis studio [SCRIPT.cs | DIR]... [--port N] [--host ADDR] [--no-open] [--nodefault] [--memory-limit SIZE]</c>:
/// the interactive demo as a local web page. Prints one line with the URL (token included) on stdout, opens
/// the default browser unless <c>--no-open</c>, and serves until Ctrl+C (exit 130). The studio itself runs as a
/// process of its own under a <see cref="StudioSupervisor"/>, which restarts it when a script ends it.
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

  readonly MemoryLimitOption memoryLimit = new();

  // The studio process's side of supervision (StudioSupervisor adds these): not for users, so not in --help.
  readonly Option<int> publicPort = new(StudioSupervisor.PublicPortOption) { Hidden = true };
  readonly Option<int> generation = new(StudioSupervisor.GenerationOption) { Hidden = true };
  readonly Option<string?> notice = new(StudioSupervisor.NoticeOption) { Hidden = true };

  public Command Build(CliEnvironment env)
  {
    var cmd = new Command("studio", "The interactive demo in the browser: render, preview, probe pixels")
    {
      paths, port, host, noOpen, noDefault, publicPort, generation, notice,
    };
    memoryLimit.AddTo(cmd);
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
    if (parse.GetValue(publicPort) != 0)
      return Serve(parse, env, options);
    if (!options.IsLoopback)
      env.Error.WriteLine($"grcis: warning: --host {address} lets other machines reach the studio; anyone with the token can run code as you");

    // Checked here, where a bad value is a usage error; the studio process applies it to itself.
    memoryLimit.Apply(parse, env with { OwnsProcess = false });
    StudioSupervisor supervisor;
    try
    {
      supervisor = StudioSupervisor.StartAsync(options, () => StudioProcess(parse), env.Error, env.Cancel).GetAwaiter().GetResult();
    }
    catch (IOException e)
    {
      throw new CliFailure($"cannot listen on {address}:{p}: {e.Message}");
    }
    catch (InvalidOperationException e)
    {
      throw new CliFailure($"the studio did not start: {e.Message}");
    }
    try
    {
      env.Out.WriteLine(supervisor.Url);
      env.Out.Flush();
      if (!parse.GetValue(noOpen))
        OpenBrowser(supervisor.Url, env);
      supervisor.WaitAsync(env.Cancel).GetAwaiter().GetResult();
    }
    finally
    {
      supervisor.DisposeAsync().AsTask().GetAwaiter().GetResult();
    }
    return ExitCodes.Cancelled;
  }

  /// <summary>
  /// The studio process a supervisor runs: <c>grcis studio</c> again, with the same scripts, folders and options
  /// (listening on a free loopback port; the supervisor adds where the user reaches it and the token).
  /// </summary>
  ProcessStartInfo StudioProcess(ParseResult parse)
  {
    // Run as an app (grcis) it starts itself; run as `dotnet exec grcis.dll` (tests, a build folder), through dotnet.
    string self = Environment.ProcessPath ?? "dotnet";
    ProcessStartInfo start;
    if (Path.GetFileNameWithoutExtension(self).Equals("grcis", StringComparison.OrdinalIgnoreCase))
      start = new ProcessStartInfo(self);
    else
    {
      string dotnet = Path.GetFileNameWithoutExtension(self).Equals("dotnet", StringComparison.OrdinalIgnoreCase) ? self
        : Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") is { Length: > 0 } host ? host : "dotnet";
      start = new ProcessStartInfo(dotnet);
      start.ArgumentList.Add("exec");
      start.ArgumentList.Add(typeof(StudioCommand).Assembly.Location);
    }
    start.ArgumentList.Add("studio");
    foreach (string path in parse.GetValue(paths) ?? [])
      start.ArgumentList.Add(path);
    start.ArgumentList.Add("--host");
    start.ArgumentList.Add(parse.GetValue(host)!);
    start.ArgumentList.Add("--no-open");
    if (parse.GetValue(noDefault))
      start.ArgumentList.Add("--nodefault");
    if (memoryLimit.Given(parse) is string limit)
    {
      start.ArgumentList.Add("--memory-limit");
      start.ArgumentList.Add(limit);
    }
    return start;
  }

  /// <summary>The longest a new studio waits for the editor's language services before it tells its address.</summary>
  static readonly TimeSpan EditorWait = TimeSpan.FromSeconds(30);

  /// <summary>The studio process under a supervisor: serves on a free loopback port until its supervisor goes.</summary>
  int Serve(ParseResult parse, CliEnvironment env, StudioOptions given)
  {
    memoryLimit.Apply(parse, env);
    StudioOptions options = given with
    {
      Port = 0,
      PublicPort = parse.GetValue(publicPort),
      Token = Environment.GetEnvironmentVariable(StudioSupervisor.TokenVariable) is { Length: > 0 } t
        ? t : throw new UsageException($"{StudioSupervisor.PublicPortOption} is for the studio's supervisor, which sets {StudioSupervisor.TokenVariable}"),
      Generation = parse.GetValue(generation),
      Notice = parse.GetValue(notice),
    };
    // Its supervisor holds the other end of its input: when that ends (the supervisor ended, even by SIGKILL), so does this.
    using var orphaned = CancellationTokenSource.CreateLinkedTokenSource(env.Cancel);
    _ = Task.Run(async () =>
    {
      await Console.OpenStandardInput().CopyToAsync(Stream.Null).ConfigureAwait(false);
      await orphaned.CancelAsync().ConfigureAwait(false);
    });
    env = env.WithCancel(orphaned.Token);

    var problems = new List<string>();
    StudioServer server;
    try
    {
      server = StudioServer.StartAsync(options, problems, env.Cancel).GetAwaiter().GetResult();
    }
    catch (IOException e)
    {
      throw new CliFailure($"cannot listen on 127.0.0.1: {e.Message}");
    }
    try
    {
      foreach (string problem in problems)
        env.Error.WriteLine("grcis: note: " + problem);
      // The address is told (and the browser opened) once the editor's completion answers, so that a page opened at once
      // finds it ready rather than seconds from ready (Roslyn's loading); a pathologically slow machine waits at most
      // EditorWait, and the page says "loading" after that. A restart after a crash answers at once: a page is waiting.
      if (options.Generation == 0 && !server.EditorReadyAsync(TimeSpan.Zero, env.Cancel).GetAwaiter().GetResult())
      {
        env.Error.WriteLine("grcis: starting the studio (loading the editor's code completion)...");
        env.Error.Flush();
        server.EditorReadyAsync(EditorWait, env.Cancel).GetAwaiter().GetResult();
      }
      env.Out.WriteLine(server.Url);
      env.Out.Flush();
      // The start is recorded: its supervisor ends this process by killing it, which would write no profile.
      StartupProfile.Finish();
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
