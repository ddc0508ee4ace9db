using System;
using System.Collections.Generic;
using System.Linq;
using System.Net;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text.Json;
using System.Threading.Tasks;

namespace GrCis.Studio.Tests;

/// <summary>
/// The studio process behind a <see cref="StudioSupervisor"/>: its access rules name the address the user reached (the
/// supervisor passes Host and Origin on), so its own port is no way round them, and its first status carries the
/// supervisor's sentence on why it was restarted.
/// </summary>
public sealed class SupervisedStudioTests : IAsyncLifetime
{
  // The supervisor's port as the studio process is told it; nothing needs to listen there for these requests.
  const int PublicPort = 45123;
  const string Token = "0123456789abcdef0123456789abcdef";
  const string Notice = "The render process overflowed its stack; the studio restarted it.";
  StudioServer server = null!;
  readonly HttpClient client = new();

  public async Task InitializeAsync() =>
    server = await StudioServer.StartAsync(new StudioOptions { PublicPort = PublicPort, Token = Token, NoDefault = true, Notice = Notice, Generation = 3 },
                                           new List<string>());

  public async Task DisposeAsync()
  {
    client.Dispose();
    await server.DisposeAsync();
  }

  HttpRequestMessage Get(string path, string? host, bool token = true, string? origin = null)
  {
    var request = new HttpRequestMessage(HttpMethod.Get, $"http://127.0.0.1:{server.Port}{path}");
    if (host != null)
      request.Headers.Host = host;
    if (token)
      request.Headers.Add(AccessGuard.HeaderName, Token);
    if (origin != null)
      request.Headers.Add("Origin", origin);
    return request;
  }

  [Fact]
  public async Task Its_own_port_is_refused_as_a_host_even_with_the_token()
  {
    Assert.NotEqual(PublicPort, server.Port);
    using HttpResponseMessage r = await client.SendAsync(Get("/api/status", host: null));
    Assert.Equal(HttpStatusCode.Forbidden, r.StatusCode);
  }

  [Fact]
  public async Task The_users_host_needs_the_token_and_sets_the_cookie_of_the_users_port()
  {
    using HttpResponseMessage without = await client.SendAsync(Get("/api/status", $"127.0.0.1:{PublicPort}", token: false));
    Assert.Equal(HttpStatusCode.Unauthorized, without.StatusCode);
    using HttpResponseMessage page = await client.SendAsync(Get($"/?token={Token}", $"localhost:{PublicPort}", token: false));
    Assert.Equal(HttpStatusCode.OK, page.StatusCode);
    Assert.StartsWith($"grcis-studio-token-{PublicPort}=", Assert.Single(page.Headers.GetValues("Set-Cookie")));
  }

  [Fact]
  public async Task Only_the_users_origin_is_its_own()
  {
    using HttpResponseMessage own = await client.SendAsync(Get("/api/scenes", $"127.0.0.1:{PublicPort}", origin: $"http://127.0.0.1:{PublicPort}"));
    Assert.Equal(HttpStatusCode.OK, own.StatusCode);
    using HttpResponseMessage inner = await client.SendAsync(Get("/api/scenes", $"127.0.0.1:{PublicPort}", origin: $"http://127.0.0.1:{server.Port}"));
    Assert.Equal(HttpStatusCode.Forbidden, inner.StatusCode);
  }

  [Fact]
  public async Task The_first_status_says_why_the_studio_process_was_restarted_and_which_it_is()
  {
    using HttpResponseMessage r = await client.SendAsync(Get("/api/status", $"127.0.0.1:{PublicPort}"));
    JsonElement status = await r.Content.ReadFromJsonAsync<JsonElement>();
    Assert.Equal(Notice, status.GetProperty("error").GetString());
    Assert.Equal(3, status.GetProperty("generation").GetInt32());
    Assert.Equal("idle", status.GetProperty("phase").GetString());

    using HttpResponseMessage work = await client.SendAsync(Get("/api/supervision", $"127.0.0.1:{PublicPort}"));
    Assert.False((await work.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("stoppedWorkRunning").GetBoolean());
  }

  [Theory]
  [InlineData(null, 134, "Stack overflow.\n   at Link.Equals(Link)", "The render process overflowed its stack; the studio restarted it.")]
  [InlineData(null, 134, "Unhandled exception. System.OutOfMemoryException: Exception of type", "The render process ran out of memory; the studio restarted it.")]
  [InlineData(null, 137, "", "The render process ran out of memory; the studio restarted it.")]
  [InlineData(null, 1, "grcis: error: something", "The render process ended unexpectedly (exit code 1); the studio restarted it.")]
  [InlineData("did not stop within 2 s and was ended", 137, "", "The render process did not stop within 2 s and was ended; the studio restarted it.")]
  public void The_page_is_told_in_one_sentence_why_the_render_process_ended(string? endedBecause, int exitCode, string errors, string sentence) =>
    Assert.Equal(sentence, WorkerEndings.Sentence(endedBecause, exitCode, errors));

  [Fact]
  public void The_stop_sentence_states_the_grace_time() =>
    Assert.Equal($"did not stop within {StudioSupervisor.StopGrace.TotalSeconds:0} s and was ended", WorkerEndings.NotStopped);
}
