using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Net;
using System.Net.Http;
using System.Net.Http.Json;
using System.Net.ServerSentEvents;
using System.Text.Json;
using System.Threading;
using System.Threading.Tasks;
using GrCis.TestSupport;

namespace GrCis.Studio.Tests;

/// <summary>
/// The event stream (<c>GET /api/events</c>): a render's progress and completion pushed with its id, Stop and a saved script
/// pushed at once, the access rules as for every request, and no stream left behind by a page that went or a studio that stopped.
/// </summary>
public sealed class EventStreamTests(StudioFixture studio) : IClassFixture<StudioFixture>
{
  /// <summary>An open event stream read one event at a time.</summary>
  sealed class Events : IAsyncDisposable
  {
    readonly HttpResponseMessage response;
    readonly IAsyncEnumerator<SseItem<string>> items;

    Events(HttpResponseMessage response, Stream stream)
    {
      this.response = response;
      items = SseParser.Create(stream).EnumerateAsync().GetAsyncEnumerator();
    }

    public static async Task<Events> Open(HttpClient client)
    {
      HttpResponseMessage response = await client.GetAsync("/api/events", HttpCompletionOption.ResponseHeadersRead);
      Assert.Equal(HttpStatusCode.OK, response.StatusCode);
      Assert.Equal("text/event-stream", response.Content.Headers.ContentType?.MediaType);
      return new Events(response, await response.Content.ReadAsStreamAsync());
    }

    /// <summary>The next event, or null when the stream ended; fails after 60 s.</summary>
    public async Task<(string Name, JsonElement Data)?> Next()
    {
      using var timeout = new CancellationTokenSource(TimeSpan.FromSeconds(60));
      if (!await items.MoveNextAsync().AsTask().WaitAsync(timeout.Token))
        return null;
      SseItem<string> item = items.Current;
      return (item.EventType, JsonDocument.Parse(item.Data.Length == 0 ? "null" : item.Data).RootElement.Clone());
    }

    /// <summary>Reads events up to and with the first that <paramref name="match"/> accepts; returns all read.</summary>
    public async Task<List<(string Name, JsonElement Data)>> Until(Func<string, JsonElement, bool> match, string what)
    {
      var read = new List<(string, JsonElement)>();
      while (await Next() is var (name, data))
      {
        read.Add((name, data));
        if (match(name, data))
          return read;
      }
      throw new InvalidOperationException($"the stream ended before {what}; read: {string.Join(", ", read.Select(e => e.Item1))}");
    }

    public async ValueTask DisposeAsync()
    {
      await items.DisposeAsync();
      response.Dispose();
    }
  }

  static long Id(JsonElement data) => data.GetProperty("renderId").GetInt64();

  async Task<long> StartRender(object body)
  {
    using HttpResponseMessage started = await studio.Client.PostAsJsonAsync("/api/render", body);
    Assert.Equal(HttpStatusCode.Accepted, started.StatusCode);
    return (await started.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("renderId").GetInt64();
  }

  [Fact]
  public async Task The_stream_shows_a_renders_progress_then_its_completion_with_its_id()
  {
    await using Events events = await Events.Open(studio.Client);
    (string first, JsonElement status) = (await events.Next())!.Value;
    Assert.Equal("status", first);
    Assert.True(status.TryGetProperty("phase", out _), status.ToString());

    long id = await StartRender(new { scene = "Five balls", settings = new { width = 320, height = 240, samplesPerPixel = 4, threads = 2 } });
    var read = await events.Until((name, data) => name == "done" && Id(data) == id, "the render's completion");
    string[] names = read.Where(e => e.Data.ValueKind == JsonValueKind.Object && e.Data.TryGetProperty("renderId", out _) && Id(e.Data) == id)
                         .Select(e => e.Name).ToArray();
    Assert.Contains("render", names);
    int progress = Array.IndexOf(names, "progress"), done = Array.IndexOf(names, "done");
    Assert.True(progress >= 0 && progress < done, string.Join(", ", names));
    Assert.Contains(read, e => e.Name == "preview" && Id(e.Data) == id);
    JsonElement completed = read[^1].Data;
    Assert.StartsWith("320x240", completed.GetProperty("statistics").GetString());
    Assert.False(completed.GetProperty("cancelled").GetBoolean());
    Assert.Equal(320, completed.GetProperty("width").GetInt32());

    // Then idle, and the status says the same.
    await events.Until((name, data) => name == "phase" && Id(data) == id && data.GetProperty("phase").GetString() == "idle", "idle after the render");
    JsonElement after = await studio.Client.GetFromJsonAsync<JsonElement>("/api/status");
    Assert.Equal(id, after.GetProperty("renderId").GetInt64());
    Assert.Equal(completed.GetProperty("version").GetInt32(), after.GetProperty("version").GetInt32());
  }

  [Fact]
  public async Task A_reconnected_stream_starts_with_the_whole_state_of_what_happened_meanwhile()
  {
    await using (Events gone = await Events.Open(studio.Client))
      Assert.Equal("status", (await gone.Next())!.Value.Name);
    long id = await StartRender(new { scene = "Five balls", settings = new { width = 24, height = 18, threads = 2 } });
    await studio.PollUntil("/api/status", s => s.GetProperty("renderId").GetInt64() == id && s.GetProperty("phase").GetString() == "idle" &&
                                                s.GetProperty("statistics").GetString() is { Length: > 0 }, "the end of the render");

    await using Events again = await Events.Open(studio.Client);
    (string name, JsonElement status) = (await again.Next())!.Value;
    Assert.Equal("status", name);
    Assert.Equal(id, Id(status));
    Assert.Equal("idle", status.GetProperty("phase").GetString());
    Assert.StartsWith("24x18", status.GetProperty("statistics").GetString());
  }

  [Fact]
  public async Task Stop_of_a_building_script_shows_up_as_the_idle_phase()
  {
    string marker = Path.Combine(studio.Folder, "events-stuck").Replace("\\", "/", StringComparison.Ordinal);
    string path = Path.Combine(studio.ScriptsFolder, "EventsStuck.cs");
    File.WriteAllText(path, StuckScripts.WhileBuilding(marker));
    using (HttpResponseMessage added = await studio.Client.PostAsJsonAsync("/api/scenes/add", new { path }))
      Assert.Equal(HttpStatusCode.OK, added.StatusCode);
    await using Events events = await Events.Open(studio.Client);
    await events.Next();
    long id = await StartRender(new { scene = "EventsStuck", settings = new { width = 8, height = 6 } });
    await events.Until((name, data) => name == "phase" && Id(data) == id && data.GetProperty("phase").GetString() == "compiling", "the compiling phase");

    using (HttpResponseMessage stop = await studio.Client.PostAsync("/api/stop", null))
      Assert.Equal(HttpStatusCode.NoContent, stop.StatusCode);
    var read = await events.Until((name, _) => name == "phase", "the phase after Stop");
    Assert.Equal("idle", read[^1].Data.GetProperty("phase").GetString());
    Assert.Equal(id, Id(read[^1].Data));
  }

  [Fact]
  public async Task A_saved_script_that_is_rendered_is_pushed_as_a_new_render_and_its_completion()
  {
    string path = Path.Combine(studio.ScriptsFolder, "EventsSaved.cs");
    File.WriteAllText(path, "Rendering.Scenes.FiveBalls(scene);\n");
    using (HttpResponseMessage added = await studio.Client.PostAsJsonAsync("/api/scenes/add", new { path }))
      Assert.Equal(HttpStatusCode.OK, added.StatusCode);
    await using Events events = await Events.Open(studio.Client);
    await events.Next();
    long first = await StartRender(new { scene = "EventsSaved", settings = new { width = 16, height = 12 } });
    await events.Until((name, data) => name == "done" && Id(data) == first, "the first render");

    using (HttpResponseMessage saved = await studio.Client.PutAsync("/api/source?scene=EventsSaved", new StringContent("Rendering.Scenes.Flags(scene);\n")))
      Assert.Equal(HttpStatusCode.NoContent, saved.StatusCode);
    var read = await events.Until((name, data) => name == "render" && Id(data) > first, "the re-render of the saved script");
    long second = Id(read[^1].Data);
    await events.Until((name, data) => name == "done" && Id(data) == second, "the re-render's completion");
  }

  [Fact]
  public async Task The_stream_is_refused_without_the_token_and_from_another_site()
  {
    using HttpResponseMessage none = await studio.Stranger.GetAsync("/api/events", HttpCompletionOption.ResponseHeadersRead);
    Assert.Equal(HttpStatusCode.Unauthorized, none.StatusCode);
    Assert.Equal("application/problem+json", none.Content.Headers.ContentType?.MediaType);

    using var foreign = new HttpRequestMessage(HttpMethod.Get, "/api/events");
    foreign.Headers.Add("Origin", "http://evil.example");
    using HttpResponseMessage refused = await studio.Client.SendAsync(foreign, HttpCompletionOption.ResponseHeadersRead);
    Assert.Equal(HttpStatusCode.Forbidden, refused.StatusCode);

    using var rebound = new HttpRequestMessage(HttpMethod.Get, "/api/events");
    rebound.Headers.Host = "evil.example";
    using HttpResponseMessage host = await studio.Client.SendAsync(rebound, HttpCompletionOption.ResponseHeadersRead);
    Assert.Equal(HttpStatusCode.Forbidden, host.StatusCode);
  }

  [Fact]
  public async Task A_stream_ends_when_its_page_goes()
  {
    // A studio of its own: the shared one may still be closing another test's stream, which would change the count.
    await using StudioServer own = await StudioServer.StartAsync(new StudioOptions { Paths = [studio.ScriptsFolder] }, new List<string>());
    using var client = new HttpClient { BaseAddress = new Uri(new Uri(own.Url).GetLeftPart(UriPartial.Authority)) };
    client.DefaultRequestHeaders.Add(AccessGuard.HeaderName, own.Token);
    Events events = await Events.Open(client);
    await events.Next();
    Assert.Equal(1, own.Session.EventStreams);
    await events.DisposeAsync();
    DateTime deadline = DateTime.UtcNow + TimeSpan.FromSeconds(30);
    while (own.Session.EventStreams != 0)
    {
      Assert.True(DateTime.UtcNow < deadline, "the stream of a page that went is still open");
      await Task.Delay(20);
    }
  }

  [Fact]
  public async Task A_studio_with_open_streams_stops_at_once_and_ends_them()
  {
    StudioServer other = await StudioServer.StartAsync(new StudioOptions { Paths = [studio.ScriptsFolder] }, new List<string>());
    using var client = new HttpClient { BaseAddress = new Uri(new Uri(other.Url).GetLeftPart(UriPartial.Authority)) };
    client.DefaultRequestHeaders.Add(AccessGuard.HeaderName, other.Token);
    await using Events one = await Events.Open(client), two = await Events.Open(client);
    await one.Next();
    await two.Next();

    var clock = Stopwatch.StartNew();
    await other.DisposeAsync();
    // Kestrel waits for open requests up to its shutdown time-out (seconds); the streams end at the stop instead.
    Assert.True(clock.Elapsed < TimeSpan.FromSeconds(3), $"the studio took {clock.Elapsed.TotalSeconds:0.0} s to stop");
    Assert.Null(await one.Next());
    Assert.Null(await two.Next());
  }

  [Fact]
  public async Task A_bad_request_is_answered_with_problem_details()
  {
    using HttpResponseMessage r = await studio.Client.PostAsJsonAsync("/api/render", new { scene = "Five balls", algorithm = "photon-mapping" });
    Assert.Equal(HttpStatusCode.BadRequest, r.StatusCode);
    Assert.Equal("application/problem+json", r.Content.Headers.ContentType?.MediaType);
    JsonElement problem = await r.Content.ReadFromJsonAsync<JsonElement>();
    Assert.Equal(400, problem.GetProperty("status").GetInt32());
    Assert.Equal("Bad Request", problem.GetProperty("title").GetString());
    Assert.Contains("algorithm 'photon-mapping' is not known", problem.GetProperty("detail").GetString());

    // An answer with only a status is problem details too.
    using HttpResponseMessage missing = await studio.Client.GetAsync("/api/no-such-endpoint");
    Assert.Equal(HttpStatusCode.NotFound, missing.StatusCode);
    Assert.Equal("application/problem+json", missing.Content.Headers.ContentType?.MediaType);
  }

  [Fact]
  public async Task The_page_is_served_from_the_assembly_with_an_entity_tag_and_a_304_when_unchanged()
  {
    using HttpResponseMessage first = await studio.Client.GetAsync("/app.js");
    Assert.Equal(HttpStatusCode.OK, first.StatusCode);
    Assert.Equal("text/javascript", first.Content.Headers.ContentType?.MediaType);
    Assert.NotNull(first.Headers.ETag);
    Assert.Contains("no-cache", first.Headers.CacheControl?.ToString());

    using var again = new HttpRequestMessage(HttpMethod.Get, "/app.js");
    again.Headers.IfNoneMatch.Add(first.Headers.ETag);
    using HttpResponseMessage second = await studio.Client.SendAsync(again);
    Assert.Equal(HttpStatusCode.NotModified, second.StatusCode);

    using HttpResponseMessage page = await studio.Client.GetAsync("/");
    Assert.Contains("<script type=\"module\" src=\"app.js\"></script>", await page.Content.ReadAsStringAsync());
  }
}
