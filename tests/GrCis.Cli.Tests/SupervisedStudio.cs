using System;
using System.Diagnostics;
using System.IO;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text.Json;
using System.Threading.Tasks;

namespace GrCis.Cli.Tests;

/// <summary>
/// <c>grcis studio DIR</c> as a real process (the supervisor and the studio process it runs), with a client that carries
/// the token as the page's cookie would.
/// </summary>
internal sealed class SupervisedStudio : IDisposable
{
  readonly Process process;

  public SupervisedStudio(string folder, params string[] options)
  {
    process = GrcisProcess.Start(folder, null, ["studio", folder, "--port", "0", "--no-open", "--nodefault", .. options]);
    // The error output is read as it comes, so the studio never blocks on a full pipe (a stack overflow's trace is long).
    _ = process.StandardError.ReadToEndAsync();
    string? url = process.StandardOutput.ReadLine();
    Assert.True(url != null && url.StartsWith("http://127.0.0.1:", StringComparison.Ordinal), $"no URL from grcis studio: '{url}'");
    var uri = new Uri(url);
    Base = new Uri($"http://127.0.0.1:{uri.Port}/");
    Token = uri.Query["?token=".Length..];
    Client = NewPage();
  }

  public Uri Base { get; }

  public string Token { get; }

  /// <summary>One page's requests.</summary>
  public HttpClient Client { get; }

  /// <summary>Another page's client (its own connections).</summary>
  public HttpClient NewPage()
  {
    var client = new HttpClient { BaseAddress = Base, Timeout = TimeSpan.FromSeconds(90) };
    client.DefaultRequestHeaders.Add("X-GrCis-Token", Token);
    return client;
  }

  public async Task<JsonElement> Status()
  {
    using HttpResponseMessage r = await Client.GetAsync("api/status");
    Assert.True(r.IsSuccessStatusCode, $"/api/status: {(int)r.StatusCode}");
    return await r.Content.ReadFromJsonAsync<JsonElement>();
  }

  /// <summary>Polls <c>/api/status</c> until <paramref name="done"/> holds (fails after <paramref name="seconds"/>).</summary>
  public async Task<JsonElement> WaitFor(Func<JsonElement, bool> done, double seconds, string what)
  {
    var clock = Stopwatch.StartNew();
    JsonElement s = await Status();
    while (!done(s))
    {
      Assert.True(clock.Elapsed.TotalSeconds < seconds, $"{what} not within {seconds} s; status: {s}");
      await Task.Delay(100);
      s = await Status();
    }
    return s;
  }

  public async Task Render(string scene, int width = 32, int height = 24)
  {
    using HttpResponseMessage r = await Client.PostAsJsonAsync("api/render", new
    {
      scene,
      settings = new { width, height, samplesPerPixel = 1, threads = 2 },
      given = new[] { "Size", "SamplesPerPixel" },
    });
    Assert.True(r.IsSuccessStatusCode, $"render {scene}: {(int)r.StatusCode} {await r.Content.ReadAsStringAsync()}");
  }

  public static string? Error(JsonElement status) => status.GetProperty("error").GetString();

  public static int Generation(JsonElement status) => status.GetProperty("generation").GetInt32();

  public void Dispose()
  {
    Client.Dispose();
    try
    {
      process.Kill(entireProcessTree: true);
      process.WaitForExit(10_000);
    }
    catch (InvalidOperationException)
    {
    }
    process.Dispose();
  }
}
