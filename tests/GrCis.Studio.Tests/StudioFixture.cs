using System;
using System.Collections.Generic;
using System.IO;
using System.Net;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text.Json;
using System.Threading.Tasks;

namespace GrCis.Studio.Tests;

/// <summary>A studio on a free loopback port over a folder with one script, and a client that knows the token.</summary>
public sealed class StudioFixture : IAsyncLifetime
{
  public string Folder { get; } = Directory.CreateTempSubdirectory("grcis-studio-").FullName;

  public StudioServer Server { get; private set; } = null!;

  public HttpClient Client { get; private set; } = null!;

  /// <summary>A client without the token.</summary>
  public HttpClient Stranger { get; private set; } = null!;

  public string ScriptsFolder => Path.Combine(Folder, "scripts");

  /// <summary>The studio's compiled-script cache, in the fixture's folder (the studio reads and fills it as <c>grcis studio</c> does).</summary>
  public string CacheFolder => Path.Combine(Folder, "cache");

  public GrCis.Scripting.Caching.ScriptCache Cache { get; private set; } = null!;

  public async Task InitializeAsync()
  {
    Directory.CreateDirectory(ScriptsFolder);
    File.WriteAllText(Path.Combine(ScriptsFolder, "Balls.cs"), "Rendering.Scenes.FiveBalls(scene);\n");
    File.WriteAllText(Path.Combine(Folder, "secret.txt"), "not for the studio");
    Directory.CreateDirectory(Path.Combine(ScriptsFolder, "more"));
    File.WriteAllText(Path.Combine(ScriptsFolder, "more", "Flags.cs"), "Rendering.Scenes.Flags(scene);\n");
    File.WriteAllText(Path.Combine(Folder, "Outside.cs"), "Rendering.Scenes.Flags(scene);\n");
    Cache = new GrCis.Scripting.Caching.ScriptCache(CacheFolder);
    Server = await StudioServer.StartAsync(new StudioOptions { Paths = [ScriptsFolder], ScriptCache = Cache }, new List<string>());
    Client = ClientOf(Server);
    Stranger = new HttpClient { BaseAddress = Client.BaseAddress };
  }

  /// <summary>A client of <paramref name="server"/> that knows its token.</summary>
  public static HttpClient ClientOf(StudioServer server)
  {
    var client = new HttpClient { BaseAddress = new Uri(new Uri(server.Url).GetLeftPart(UriPartial.Authority)) };
    client.DefaultRequestHeaders.Add(AccessGuard.HeaderName, server.Token);
    return client;
  }

  /// <summary>Polls <c>GET <paramref name="path"/></c> until <paramref name="done"/> holds for its JSON (60 s at most).</summary>
  public Task<JsonElement> PollUntil(string path, Func<JsonElement, bool> done, string what) => PollUntil(Client, path, done, what);

  /// <summary>As <see cref="PollUntil(string, Func{JsonElement, bool}, string)"/>, asking <paramref name="client"/>'s studio.</summary>
  public static async Task<JsonElement> PollUntil(HttpClient client, string path, Func<JsonElement, bool> done, string what)
  {
    var deadline = DateTime.UtcNow + TimeSpan.FromSeconds(60);
    while (DateTime.UtcNow < deadline)
    {
      JsonElement answer = await client.GetFromJsonAsync<JsonElement>(path);
      if (done(answer))
        return answer;
      await Task.Delay(50);
    }
    throw new TimeoutException($"the studio did not get to {what}");
  }

  /// <summary>Asks for a render and waits until it has finished; returns the status then.</summary>
  public Task<JsonElement> RenderAndWait(object body) => RenderAndWait(Client, body);

  /// <summary>As <see cref="RenderAndWait(object)"/>, in <paramref name="client"/>'s studio.</summary>
  public static async Task<JsonElement> RenderAndWait(HttpClient client, object body)
  {
    using HttpResponseMessage started = await client.PostAsJsonAsync("/api/render", body);
    Assert.Equal(HttpStatusCode.Accepted, started.StatusCode);
    return await PollUntil(client, "/api/status",
      s => !s.GetProperty("rendering").GetBoolean() && s.GetProperty("statistics").GetString() is { Length: > 0 }, "the end of the render");
  }

  /// <summary>Asks for an animation and waits until it has finished; returns the animation's status then.</summary>
  public async Task<JsonElement> AnimateAndWait(object body)
  {
    using (HttpResponseMessage started = await StartAnimation(body))
      Assert.Equal(HttpStatusCode.Accepted, started.StatusCode);
    return await PollUntil("/api/animation", a => !a.GetProperty("running").GetBoolean(), "the end of the animation");
  }

  /// <summary>
  /// Asks for an animation, once, as the page does: the studio itself lets a render that has ended (or was stopped)
  /// finish before it answers, so only a render still busy is refused (409).
  /// </summary>
  public Task<HttpResponseMessage> StartAnimation(object body) => Client.PostAsJsonAsync("/api/animation", body);

  public async Task DisposeAsync()
  {
    Client.Dispose();
    Stranger.Dispose();
    await Server.DisposeAsync();
    Directory.Delete(Folder, recursive: true);
  }
}
