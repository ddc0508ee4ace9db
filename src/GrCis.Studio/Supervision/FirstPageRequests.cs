using System;
using System.Net.Http;
using System.Net.Http.Json;
using System.Threading;
using System.Threading.Tasks;

namespace GrCis.Studio;

/// <summary>
/// A page's first requests (the page, the status, a completion), made by the supervisor through its own port before it
/// tells the address. The first request of a process pays for compiling its way through Kestrel, the forwarder, the
/// access rules and the endpoint (a second on a loaded 2-core machine): made here, a user's page does not meet it.
/// </summary>
internal static class FirstPageRequests
{
  static readonly TimeSpan Limit = TimeSpan.FromSeconds(10);

  /// <summary>
  /// Makes the requests to the studio listening on <paramref name="options"/>' address and <paramref name="port"/>, as a
  /// page with <paramref name="token"/> at <paramref name="hostHeader"/> would; best effort: a failure or a slow answer
  /// only ends it (the studio answers the user's page all the same).
  /// </summary>
  public static async Task MakeAsync(StudioOptions options, int port, string hostHeader, string token, CancellationToken cancel)
  {
    string host = options.IsAnyAddress || options.Host == "localhost" ? "127.0.0.1" : StudioOptions.UrlHost(options.Host);
    using var client = new HttpClient { BaseAddress = new Uri($"http://{host}:{port}/"), Timeout = Limit };
    client.DefaultRequestHeaders.Host = hostHeader;
    client.DefaultRequestHeaders.Add(AccessGuard.HeaderName, token);
    using var limit = CancellationTokenSource.CreateLinkedTokenSource(cancel);
    limit.CancelAfter(Limit);
    try
    {
      using (HttpResponseMessage page = await client.GetAsync("", limit.Token).ConfigureAwait(false)) { }
      using (HttpResponseMessage status = await client.GetAsync("api/status", limit.Token).ConfigureAwait(false)) { }
      const string text = "scene.";
      using (HttpResponseMessage complete = await client.PostAsJsonAsync("api/editor/complete", new { text, position = text.Length }, limit.Token)
               .ConfigureAwait(false)) { }
    }
    catch (Exception e) when (e is HttpRequestException or OperationCanceledException)
    {
      cancel.ThrowIfCancellationRequested();
    }
  }
}
