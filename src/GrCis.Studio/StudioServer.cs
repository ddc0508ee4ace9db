using System;
using System.Collections.Generic;
using System.Linq;
using System.Net;
using System.Text.Json.Serialization;
using System.Threading;
using System.Threading.Tasks;
using GrCis.Interactive;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Hosting;
using Microsoft.AspNetCore.Hosting.Server;
using Microsoft.AspNetCore.Hosting.Server.Features;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Http.Json;
using Microsoft.AspNetCore.Routing;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.FileProviders;
using Microsoft.Extensions.Logging;

namespace GrCis.Studio;

/// <summary>
/// <c>grcis studio</c>: the interactive demo as a local web page. One Kestrel server on <see cref="StudioOptions.Host"/>
/// (loopback by default) serves the page from the assembly and a small JSON/PNG API over one
/// <see cref="DemoController"/> (<see cref="StudioApi"/>, its changes pushed as events by <see cref="StudioEvents"/>),
/// all behind the <see cref="AccessGuard"/>; every error is a problem details document (RFC 7807).
/// </summary>
public sealed class StudioServer : IAsyncDisposable
{
  readonly WebApplication app;

  StudioServer(WebApplication app, StudioSession session, string token, string url)
  {
    this.app = app;
    Session = session;
    Token = token;
    Url = url;
  }

  public StudioSession Session { get; }

  public string Token { get; }

  /// <summary>The address to open, token included.</summary>
  public string Url { get; }

  /// <summary>Port the server listens on (the free one chosen for <c>--port 0</c>).</summary>
  public int Port => new Uri(Url).Port;

  /// <summary>Starts listening; returns when the server accepts requests.</summary>
  /// <param name="problems">Where command-line problems go (a missing script or folder); the rest still loads.</param>
  public static async Task<StudioServer> StartAsync(StudioOptions options, ICollection<string> problems, CancellationToken cancel = default)
  {
    ArgumentNullException.ThrowIfNull(options);
    var args = new List<string>();
    foreach (string p in options.Paths)
    {
      args.Add(System.IO.Directory.Exists(p) ? "-dir" : "-scene");
      args.Add(p);
    }
    if (options.NoDefault)
      args.Add("-nodefault");
    var scripts = new GrCis.Scripting.ScriptHost(diskCache: options.ScriptCache);
    var files = new AllowedFiles(options.Paths);
    var controller = DemoController.FromCommandLine(args, scripts, problems, files.Allows);
    var session = new StudioSession(controller) { Scripts = scripts, Notice = options.Notice, Generation = options.Generation };
    string token = options.Token ?? AccessGuard.NewToken();
    // The editor's language services load (Roslyn's metadata and its first completion: seconds) while the server starts
    // and the user opens the page, on the second core, not on the page's first completion.
    var editor = new EditorAssistance(session);
    if (options.WarmEditor)
      _ = editor.WarmAsync();

    WebApplicationBuilder builder = WebApplication.CreateSlimBuilder();
    builder.Logging.ClearProviders();
    builder.WebHost.ConfigureKestrel(k =>
    {
      // Behind a supervisor, only the supervisor forwards here: this machine's loopback is enough.
      if (options.PublicPort != 0)
        k.Listen(IPAddress.Loopback, options.Port);
      else if (options.Host == "localhost")
        k.ListenLocalhost(options.Port);
      else
        k.Listen(IPAddress.Parse(options.Host.Trim('[', ']')), options.Port);
    });
    builder.Services.Configure<JsonOptions>(o => o.SerializerOptions.Converters.Add(new JsonStringEnumConverter()));
    // A body that is not JSON, or not the endpoint's shape, is a 400 whose problem details say what was wrong
    // (without this, minimal APIs answer such a request with a bare 400).
    builder.Services.Configure<RouteHandlerOptions>(o => o.ThrowOnBadRequest = true);
    builder.Services.AddProblemDetails(o => o.CustomizeProblemDetails = c =>
    {
      if (c.Exception is BadHttpRequestException bad)
      {
        c.ProblemDetails.Status = bad.StatusCode;
        c.ProblemDetails.Detail = bad.InnerException is System.Text.Json.JsonException json
          ? $"The request body is not valid JSON for this request: {json.Message}"
          : $"The request is malformed: {bad.Message}";
      }
    });
    builder.Services.AddSingleton(session);
    builder.Services.AddSingleton(files);
    // Made by a factory, so the container disposes it with the server (which ends a warm-up still running).
    builder.Services.AddSingleton(_ => editor);
    WebApplication app = builder.Build();

    // A failure inside an endpoint, and an answer with a status and no body (a 404 of an image not rendered yet), are
    // problem details too.
    app.UseExceptionHandler(new ExceptionHandlerOptions { StatusCodeSelector = e => e is BadHttpRequestException bad ? bad.StatusCode : 500 });
    app.UseStatusCodePages();

    // The port is known only once Kestrel listens (--port 0): the guard reads the hosts it allows then.
    AccessGuard? guard = null;
    app.Use((context, next) =>
    {
      if (Volatile.Read(ref guard) is AccessGuard g)
        return g.InvokeAsync(context, _ => next());
      context.Response.StatusCode = Microsoft.AspNetCore.Http.StatusCodes.Status503ServiceUnavailable;
      return Task.CompletedTask;
    });
    // The page: its files as built into the assembly, read in place (no copy per request), with an entity tag so a
    // reload costs a 304; "no-cache" makes the browser ask, so a new studio's page is never an old one from the cache.
    var page = new EmbeddedFileProvider(typeof(StudioServer).Assembly, "page");
    app.UseDefaultFiles(new DefaultFilesOptions { FileProvider = page });
    app.UseStaticFiles(new StaticFileOptions
    {
      FileProvider = page,
      OnPrepareResponse = f => f.Context.Response.Headers.CacheControl = "no-cache",
    });
    app.MapStudioApi();
    try
    {
      await app.StartAsync(cancel).ConfigureAwait(false);
    }
    catch
    {
      await app.DisposeAsync().ConfigureAwait(false);
      session.Dispose();
      throw;
    }

    // Kestrel listens on the one endpoint configured above, so its one address names the port.
    int port = new Uri(app.Services.GetRequiredService<IServer>().Features.Get<IServerAddressesFeature>()!.Addresses.First()).Port;
    // The rules name the address the user reaches: a supervisor's port when one forwards here (it passes Host and Origin on).
    int reached = options.PublicPort != 0 ? options.PublicPort : port;
    Volatile.Write(ref guard, new AccessGuard(token, AccessGuard.HostsFor(options.Host, reached, options.IsLoopback), options.IsAnyAddress ? reached : 0, reached));
    string shown = options.IsLoopback ? "127.0.0.1" : StudioOptions.UrlHost(options.Host);
    return new StudioServer(app, session, token, $"http://{shown}:{port}/?token={token}");
  }

  /// <summary>
  /// Runs until <paramref name="cancel"/> is signalled (Ctrl+C) or the host is told to stop (SIGTERM, which the
  /// host's console lifetime turns into a stop of the application), then stops the render and the server.
  /// </summary>
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

  /// <summary>
  /// Waits until the editor's language services answer at their warm speed, at most <paramref name="within"/>: false when
  /// they are still loading then (the page then says so until they are). <c>grcis studio</c> tells its address after this,
  /// so a page opened at once finds completion ready.
  /// </summary>
  public async Task<bool> EditorReadyAsync(TimeSpan within, CancellationToken cancel)
  {
    try
    {
      await Editor.ReadyAsync(cancel).WaitAsync(within, cancel).ConfigureAwait(false);
      return true;
    }
    catch (TimeoutException)
    {
      return false;
    }
  }

  /// <summary>The studio's editor services (tests look at their warm-up).</summary>
  internal EditorAssistance Editor => app.Services.GetRequiredService<EditorAssistance>();

  public async ValueTask DisposeAsync()
  {
    Session.Stop();
    await app.StopAsync().ConfigureAwait(false);
    await app.DisposeAsync().ConfigureAwait(false);
    Session.Dispose();
  }
}
