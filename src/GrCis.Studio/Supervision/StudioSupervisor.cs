using System;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Net;
using System.Net.Http;
using System.Net.Http.Json;
using System.Net.Sockets;
using System.Text.Json;
using System.Text.Json.Serialization;
using System.Threading;
using System.Threading.Tasks;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Hosting;
using Microsoft.AspNetCore.Hosting.Server;
using Microsoft.AspNetCore.Hosting.Server.Features;
using Microsoft.AspNetCore.Http;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Logging;
using Yarp.ReverseProxy.Forwarder;

namespace GrCis.Studio;

/// <summary>
/// <c>grcis studio</c> as Jupyter runs kernels: this small server owns the address and the token the user was given and
/// runs the studio itself (<see cref="StudioServer"/>) as a process of its own on a private loopback port, forwarding
/// every request to it (YARP). Scene scripts run in that process, so a script that overflows the stack, runs out of
/// memory or ignores Stop ends that process, not the studio: the supervisor starts a new one, answers the page meanwhile
/// (<c>/api/status</c> and the event stream say <c>restarting</c> and why), and the new process's page shows one sentence
/// on what happened (<see cref="WorkerEndings"/>). Stop always stops: when what it stopped still runs
/// <see cref="StopGrace"/> later, the process is ended and restarted.
/// </summary>
public sealed class StudioSupervisor : IAsyncDisposable
{
  /// <summary>Carries the token to the studio process (an environment variable, which other users cannot read, unlike arguments).</summary>
  public const string TokenVariable = "GRCIS_STUDIO_TOKEN";

  /// <summary>The studio process's options (<see cref="StudioOptions.PublicPort"/>, <see cref="StudioOptions.Generation"/>, <see cref="StudioOptions.Notice"/>).</summary>
  public const string PublicPortOption = "--public-port";

  public const string GenerationOption = "--generation";

  public const string NoticeOption = "--notice";

  /// <summary>How long what Stop stopped may keep running before the studio process is ended.</summary>
  public static readonly TimeSpan StopGrace = TimeSpan.FromSeconds(2);

  // A loaded machine's studio process may take this long to listen; a request waits as long for a restarting one.
  static readonly TimeSpan StartTimeout = TimeSpan.FromSeconds(60);

  static readonly JsonSerializerOptions Json = new(JsonSerializerDefaults.Web) { Converters = { new JsonStringEnumConverter() } };

  // Every byte streams through as it comes (the event stream included); a long compile answers late, not never.
  static readonly ForwarderRequestConfig Forwarding = new() { ActivityTimeout = TimeSpan.FromMinutes(10) };

  readonly WebApplication app;
  readonly Func<ProcessStartInfo> command;
  readonly TextWriter errors;
  readonly HttpMessageInvoker client = new(new SocketsHttpHandler
  {
    UseProxy = false,
    AllowAutoRedirect = false,
    AutomaticDecompression = DecompressionMethods.None,
    UseCookies = false,
    ActivityHeadersPropagator = null,
    ConnectTimeout = TimeSpan.FromSeconds(15),
  });
  readonly CancellationTokenSource closing = new();
  readonly object sync = new();
  // The studio process that answers; null while a new one starts, which `restarted` then gives.
  StudioWorker? worker;
  TaskCompletionSource<StudioWorker> restarted = new(TaskCreationOptions.RunContinuationsAsynchronously);
  string? restartingBecause;
  int generation;
  Task supervising = Task.CompletedTask;
  string token = "";
  // The listening socket taken before Kestrel started (it listens on it); closed after Kestrel.
  Socket? taken;
  string hostHeader = "";

  StudioSupervisor(WebApplication app, Func<ProcessStartInfo> command, TextWriter errors)
  {
    this.app = app;
    this.command = command;
    this.errors = errors;
  }

  /// <summary>The address to open, token included.</summary>
  public string Url { get; private set; } = "";

  /// <summary>The port the user reaches the studio on.</summary>
  public int Port { get; private set; }

  /// <summary>The studio process answering now (tests end it); 0 while one starts.</summary>
  public int WorkerProcessId
  {
    get
    {
      lock (sync)
        return worker?.ProcessId ?? 0;
    }
  }

  /// <summary>
  /// Listens on <paramref name="options"/>' address, starts the studio process (<paramref name="command"/>: the
  /// <c>grcis studio</c> command line of the scripts and folders, to which the supervisor adds its own options and the
  /// token) and returns once it answers.
  /// </summary>
  /// <param name="errors">Where the studio process's error output goes, and the supervisor's word on each restart.</param>
  /// <exception cref="IOException">The address is in use.</exception>
  /// <exception cref="InvalidOperationException">The studio process did not start; the message says why.</exception>
  public static async Task<StudioSupervisor> StartAsync(StudioOptions options, Func<ProcessStartInfo> command, TextWriter errors,
                                                        CancellationToken cancel = default)
  {
    ArgumentNullException.ThrowIfNull(options);
    // The address is taken first, in microseconds, so the studio process (which must know the port) starts while this
    // server is built, not after: the two start-ups overlap. Kestrel then listens on that socket. Where it cannot take a
    // socket (Windows) or the name is localhost (two addresses), it binds by itself and the studio process starts after.
    Socket? taken = OperatingSystem.IsWindows() || options.Host == "localhost" ? null : Take(options);
    WebApplicationBuilder builder = WebApplication.CreateSlimBuilder();
    builder.Logging.ClearProviders();
    builder.WebHost.ConfigureKestrel(k =>
    {
      if (taken != null)
        k.ListenHandle((ulong)taken.SafeHandle.DangerousGetHandle());
      else if (options.Host == "localhost")
        k.ListenLocalhost(options.Port);
      else
        k.Listen(IPAddress.Parse(options.Host.Trim('[', ']')), options.Port);
    });
    builder.Services.AddProblemDetails();
    builder.Services.AddHttpForwarder();
    WebApplication app = builder.Build();
    var supervisor = new StudioSupervisor(app, command, errors) { token = options.Token ?? AccessGuard.NewToken(), taken = taken };
    Task<StudioWorker>? starting = null;
    if (taken != null)
    {
      supervisor.Port = ((IPEndPoint)taken.LocalEndPoint!).Port;
      starting = StudioWorker.StartAsync(supervisor.StartInfo(0, null), errors, StartTimeout, cancel);
    }

    // The supervisor's own answers (while the studio process restarts) obey the studio's rules too; the studio process
    // checks every forwarded request again, so its port is no way round them.
    AccessGuard? guard = null;
    app.Use((context, next) =>
    {
      if (Volatile.Read(ref guard) is AccessGuard g)
        return g.InvokeAsync(context, _ => next());
      context.Response.StatusCode = StatusCodes.Status503ServiceUnavailable;
      return Task.CompletedTask;
    });
    app.Run(supervisor.AnswerAsync);
    try
    {
      await app.StartAsync(cancel).ConfigureAwait(false);
      int port = taken != null ? supervisor.Port
        : new Uri(app.Services.GetRequiredService<IServer>().Features.Get<IServerAddressesFeature>()!.Addresses.First()).Port;
      supervisor.Port = port;
      supervisor.hostHeader = AccessGuard.HostsFor(options.Host, port, options.IsLoopback).First();
      Volatile.Write(ref guard, new AccessGuard(supervisor.token, AccessGuard.HostsFor(options.Host, port, options.IsLoopback),
                                                options.IsAnyAddress ? port : 0, port));
      starting ??= StudioWorker.StartAsync(supervisor.StartInfo(0, null), errors, StartTimeout, cancel);
      StudioWorker first = await starting.ConfigureAwait(false);
      lock (supervisor.sync)
        supervisor.worker = first;
      supervisor.supervising = supervisor.SuperviseAsync(first);
      await FirstPageRequests.MakeAsync(options, port, supervisor.hostHeader, supervisor.token, cancel).ConfigureAwait(false);
      string shown = options.IsLoopback ? "127.0.0.1" : StudioOptions.UrlHost(options.Host);
      supervisor.Url = $"http://{shown}:{port}/?token={supervisor.token}";
      return supervisor;
    }
    catch
    {
      if (starting != null)
        (await starting.ContinueWith(t => t.IsCompletedSuccessfully ? t.Result : null, TaskScheduler.Default).ConfigureAwait(false))?.Dispose();
      await supervisor.DisposeAsync().ConfigureAwait(false);
      throw;
    }
  }

  /// <summary>A socket bound and listening on the studio's address.</summary>
  /// <exception cref="IOException">The address is in use (or not this machine's).</exception>
  static Socket Take(StudioOptions options)
  {
    IPAddress address = IPAddress.Parse(options.Host.Trim('[', ']'));
    var socket = new Socket(address.AddressFamily, SocketType.Stream, ProtocolType.Tcp);
    try
    {
      socket.Bind(new IPEndPoint(address, options.Port));
      socket.Listen(512);
      return socket;
    }
    catch (SocketException e)
    {
      socket.Dispose();
      throw new IOException(e.Message, e);
    }
  }

  ProcessStartInfo StartInfo(int number, string? notice)
  {
    ProcessStartInfo start = command();
    start.ArgumentList.Add(PublicPortOption);
    start.ArgumentList.Add(Port.ToString(System.Globalization.CultureInfo.InvariantCulture));
    start.ArgumentList.Add(GenerationOption);
    start.ArgumentList.Add(number.ToString(System.Globalization.CultureInfo.InvariantCulture));
    if (notice != null)
    {
      start.ArgumentList.Add(NoticeOption);
      start.ArgumentList.Add(notice);
    }
    start.Environment[TokenVariable] = token;
    return start;
  }

  // Each time the studio process ends, a new one, told why the last one ended (the page's first message).
  async Task SuperviseAsync(StudioWorker current)
  {
    while (true)
    {
      try
      {
        await current.Exited.WaitAsync(closing.Token).ConfigureAwait(false);
      }
      catch (OperationCanceledException)
      {
        return;
      }
      string why = current.Explain();
      current.Dispose();
      int number;
      lock (sync)
      {
        worker = null;
        restartingBecause = why;
        number = ++generation;
      }
      Say($"grcis: {why}");
      while (true)
      {
        try
        {
          current = await StudioWorker.StartAsync(StartInfo(number, why), errors, StartTimeout, closing.Token).ConfigureAwait(false);
          break;
        }
        catch (OperationCanceledException)
        {
          return;
        }
        catch (InvalidOperationException e)
        {
          Say($"grcis: the render process did not restart ({e.Message}); trying again");
          try
          {
            await Task.Delay(TimeSpan.FromSeconds(1), closing.Token).ConfigureAwait(false);
          }
          catch (OperationCanceledException)
          {
            return;
          }
        }
      }
      TaskCompletionSource<StudioWorker> waiting;
      lock (sync)
      {
        worker = current;
        restartingBecause = null;
        waiting = restarted;
        restarted = new(TaskCreationOptions.RunContinuationsAsynchronously);
      }
      waiting.TrySetResult(current);
    }
  }

  void Say(string line)
  {
    lock (errors)
    {
      errors.WriteLine(line);
      errors.Flush();
    }
  }

  // Every request goes to the studio process; while a new one starts, the status and the event stream say so, and
  // anything else waits for it.
  async Task AnswerAsync(HttpContext context)
  {
    string path = context.Request.Path.Value ?? "";
    Task<StudioWorker> answering;
    string? why;
    lock (sync)
    {
      answering = worker != null ? Task.FromResult(worker) : restarted.Task;
      why = restartingBecause;
    }
    if (!answering.IsCompleted && why != null)
    {
      if (path is "/api/status" or "/api/events")
      {
        await RestartingAnswers.AnswerAsync(context, why, answering, Json).ConfigureAwait(false);
        return;
      }
    }
    StudioWorker to;
    try
    {
      to = await answering.WaitAsync(StartTimeout, context.RequestAborted).ConfigureAwait(false);
    }
    catch (TimeoutException)
    {
      await TypedResults.Problem(statusCode: StatusCodes.Status503ServiceUnavailable,
        detail: "grcis studio: the render process is restarting and does not answer yet; try again in a moment").ExecuteAsync(context).ConfigureAwait(false);
      return;
    }
    catch (OperationCanceledException)
    {
      return;
    }
    bool stop = HttpMethods.IsPost(context.Request.Method) && path == "/api/stop";
    // The studio process checks the request again and sets the token's cookie itself: once is enough.
    context.Response.Headers.Remove(Microsoft.Net.Http.Headers.HeaderNames.SetCookie);
    IHttpForwarder forwarder = context.RequestServices.GetRequiredService<IHttpForwarder>();
    ForwarderError error = await forwarder.SendAsync(context, to.Prefix, client, Forwarding, UserHostTransformer.Instance).ConfigureAwait(false);
    // A request that reached a studio process as it ended, and can be asked again (no body), goes to the next one.
    if (error != ForwarderError.None && !context.Response.HasStarted && (HttpMethods.IsGet(context.Request.Method) || HttpMethods.IsHead(context.Request.Method)) &&
        await to.Exited.WaitAsync(TimeSpan.FromSeconds(2), context.RequestAborted).ContinueWith(t => t.IsCompletedSuccessfully, TaskScheduler.Default).ConfigureAwait(false) &&
        await NextAfterAsync(to, context.RequestAborted).ConfigureAwait(false) is StudioWorker next)
    {
      context.Response.Clear();
      context.Response.StatusCode = StatusCodes.Status200OK;
      error = await forwarder.SendAsync(context, next.Prefix, client, Forwarding, UserHostTransformer.Instance).ConfigureAwait(false);
    }
    if (stop && error == ForwarderError.None)
      _ = EnsureStoppedAsync(to);
  }

  // The studio process after the one that ended; null when none answers within the start time (or the request went).
  async Task<StudioWorker?> NextAfterAsync(StudioWorker ended, CancellationToken cancel)
  {
    var clock = Stopwatch.StartNew();
    while (clock.Elapsed < StartTimeout && !cancel.IsCancellationRequested)
    {
      lock (sync)
        if (worker != null && worker != ended)
          return worker;
      try
      {
        await Task.Delay(50, cancel).ConfigureAwait(false);
      }
      catch (OperationCanceledException)
      {
        return null;
      }
    }
    return null;
  }

  // Stop always stops: what it stopped still running after the grace time (a loop that never looks at the stop) ends
  // the studio process, as does a process that no longer answers.
  async Task EnsureStoppedAsync(StudioWorker stopped)
  {
    try
    {
      await Task.Delay(StopGrace, closing.Token).ConfigureAwait(false);
    }
    catch (OperationCanceledException)
    {
      return;
    }
    if (stopped.Exited.IsCompleted)
      return;
    bool? running = await StoppedWorkRunningAsync(stopped).ConfigureAwait(false);
    if (running != false)
      stopped.End(running == null ? WorkerEndings.NotAnswering : WorkerEndings.NotStopped);
  }

  async Task<bool?> StoppedWorkRunningAsync(StudioWorker asked)
  {
    using var request = new HttpRequestMessage(HttpMethod.Get, asked.Prefix + "api/supervision");
    request.Headers.Host = hostHeader;
    request.Headers.Add(AccessGuard.HeaderName, token);
    using var timeout = CancellationTokenSource.CreateLinkedTokenSource(closing.Token);
    timeout.CancelAfter(StopGrace);
    try
    {
      using HttpResponseMessage response = await client.SendAsync(request, timeout.Token).ConfigureAwait(false);
      if (!response.IsSuccessStatusCode)
        return null;
      SupervisionApi.WorkJson? work = await response.Content.ReadFromJsonAsync<SupervisionApi.WorkJson>(Json, timeout.Token).ConfigureAwait(false);
      return work?.StoppedWorkRunning;
    }
    catch (Exception e) when (e is HttpRequestException or OperationCanceledException or JsonException)
    {
      return closing.IsCancellationRequested ? false : null;
    }
  }

  /// <summary>Runs until <paramref name="cancel"/> is signalled (Ctrl+C) or the host is told to stop (SIGTERM).</summary>
  public async Task WaitAsync(CancellationToken cancel)
  {
    using var either = CancellationTokenSource.CreateLinkedTokenSource(cancel, app.Lifetime.ApplicationStopping);
    try
    {
      await Task.Delay(Timeout.Infinite, either.Token).ConfigureAwait(false);
    }
    catch (OperationCanceledException)
    {
    }
  }

  /// <summary>Ends the studio process and stops listening.</summary>
  public async ValueTask DisposeAsync()
  {
    await closing.CancelAsync().ConfigureAwait(false);
    StudioWorker? last;
    lock (sync)
      last = worker;
    last?.Dispose();
    await supervising.ConfigureAwait(false);
    await app.StopAsync().ConfigureAwait(false);
    await app.DisposeAsync().ConfigureAwait(false);
    client.Dispose();
    closing.Dispose();
    taken?.Dispose();
  }
}
