using System;
using System.IO;
using System.Net;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text.Json;
using System.Threading.Tasks;
using GrCis.TestSupport;

namespace GrCis.Studio.Tests;

/// <summary>
/// The studio's status can be trusted: busy while the script of the render asked for last builds, idle at once after
/// Stop, the second of two renders is the one reported, an error stays until the next action, and Stop ends an
/// animation too.
/// </summary>
public sealed class StateTests(StudioFixture studio) : IClassFixture<StudioFixture>
{
  async Task<string> AddScript(string file, string text)
  {
    string path = Path.Combine(studio.ScriptsFolder, file);
    File.WriteAllText(path, text);
    using HttpResponseMessage added = await studio.Client.PostAsJsonAsync("/api/scenes/add", new { path });
    Assert.Equal(HttpStatusCode.OK, added.StatusCode);
    return (await added.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("name").GetString()!;
  }

  Task<JsonElement> Status() => studio.Client.GetFromJsonAsync<JsonElement>("/api/status");

  /// <summary>Asks for a small render of <paramref name="scene"/> and waits until its script writes <paramref name="marker"/>.</summary>
  async Task RenderUntil(string scene, string marker, string what, int width = 8, int height = 6)
  {
    using (HttpResponseMessage started = await studio.Client.PostAsJsonAsync("/api/render", new { scene, settings = new { width, height } }))
      Assert.Equal(HttpStatusCode.Accepted, started.StatusCode);
    DateTime deadline = DateTime.UtcNow + TimeSpan.FromMinutes(1);
    while (!File.Exists(marker))
    {
      Assert.True(DateTime.UtcNow < deadline, what);
      await Task.Delay(20);
    }
  }

  [Fact]
  public async Task A_building_script_is_busy_and_stop_makes_the_studio_idle_at_once()
  {
    string marker = Path.Combine(studio.Folder, "stuck-started").Replace("\\", "/", StringComparison.Ordinal);
    await RenderUntil(await AddScript("StuckBuild.cs", StuckScripts.WhileBuilding(marker)), marker, "the script never started");
    JsonElement building = await Status();
    Assert.True(building.GetProperty("rendering").GetBoolean(), "busy while the script builds");
    Assert.Equal("compiling", building.GetProperty("phase").GetString());
    using (HttpResponseMessage stop = await studio.Client.PostAsync("/api/stop", null))
      Assert.Equal(HttpStatusCode.NoContent, stop.StatusCode);
    JsonElement stopped = await Status();
    Assert.False(stopped.GetProperty("rendering").GetBoolean(), "still 'rendering' after Stop");
    Assert.Equal("idle", stopped.GetProperty("phase").GetString());
  }

  [Fact]
  public async Task The_phase_is_rendering_once_the_script_is_built_and_idle_after_stop()
  {
    string marker = Path.Combine(studio.Folder, "stuck-rendering").Replace("\\", "/", StringComparison.Ordinal);
    await RenderUntil(await AddScript("StuckRender.cs", StuckScripts.WhileRendering(marker)), marker, "the render never reached the script's texture");
    JsonElement rendering = await Status();
    Assert.True(rendering.GetProperty("rendering").GetBoolean());
    Assert.Equal("rendering", rendering.GetProperty("phase").GetString());
    using (HttpResponseMessage stop = await studio.Client.PostAsync("/api/stop", null))
      Assert.Equal(HttpStatusCode.NoContent, stop.StatusCode);
    Assert.Equal("idle", (await Status()).GetProperty("phase").GetString());
  }

  [Fact]
  public async Task The_second_of_two_renders_is_the_one_reported()
  {
    using (HttpResponseMessage first = await studio.Client.PostAsJsonAsync("/api/render",
             new { scene = "Five balls", settings = new { width = 1200, height = 900, samplesPerPixel = 16, threads = 2 } }))
      Assert.Equal(HttpStatusCode.Accepted, first.StatusCode);
    await studio.PollUntil("/api/status", s => s.GetProperty("version").GetInt32() > 0 || s.GetProperty("fraction").GetDouble() > 0, "the first render's progress");
    long replaced = (await Status()).GetProperty("renderId").GetInt64();
    JsonElement done = await studio.RenderAndWait(new { scene = "Five balls", settings = new { width = 40, height = 30, threads = 2 } });
    Assert.Equal(replaced + 1, done.GetProperty("renderId").GetInt64());
    Assert.StartsWith("40x30", done.GetProperty("statistics").GetString());
    Assert.Equal(40, done.GetProperty("width").GetInt32());
    // Still the second's a while later: the replaced render's completion was not taken for it.
    await Task.Delay(300);
    JsonElement later = await Status();
    Assert.False(later.GetProperty("rendering").GetBoolean());
    Assert.StartsWith("40x30", later.GetProperty("statistics").GetString());
  }

  [Fact]
  public async Task The_status_names_the_tab_whose_render_is_on_show()
  {
    async Task RenderFrom(string tab)
    {
      using var request = new HttpRequestMessage(HttpMethod.Post, "/api/render")
      {
        Content = JsonContent.Create(new { scene = "Five balls", settings = new { width = 16, height = 12 } }),
      };
      request.Headers.Add(StudioSession.TabHeader, tab);
      using HttpResponseMessage started = await studio.Client.SendAsync(request);
      Assert.Equal(HttpStatusCode.Accepted, started.StatusCode);
    }
    await RenderFrom("first-tab");
    Assert.Equal("first-tab", (await Status()).GetProperty("tab").GetString());
    await RenderFrom("second-tab");
    Assert.Equal("second-tab", (await Status()).GetProperty("tab").GetString());
    await studio.PollUntil("/api/status", s => s.GetProperty("phase").GetString() == "idle", "the end of the render");
  }

  [Fact]
  public async Task An_error_stays_until_the_next_action()
  {
    string name = await AddScript("Typo.cs", "scene.NoSuchMember = 2;\n");
    using (HttpResponseMessage started = await studio.Client.PostAsJsonAsync("/api/render", new { scene = name, settings = new { width = 8, height = 6 } }))
      Assert.Equal(HttpStatusCode.Accepted, started.StatusCode);
    JsonElement failed = await studio.PollUntil("/api/status", s => s.GetProperty("error").ValueKind == JsonValueKind.String, "the script's error");
    Assert.False(failed.GetProperty("rendering").GetBoolean());
    for (int i = 0; i < 5; i++)
    {
      await Task.Delay(100);
      Assert.Contains("Typo.cs", (await Status()).GetProperty("error").GetString());
    }
    JsonElement next = await studio.RenderAndWait(new { scene = "Five balls", settings = new { width = 16, height = 12 } });
    Assert.Equal(JsonValueKind.Null, next.GetProperty("error").ValueKind);
  }

  [Fact]
  public async Task Stop_ends_an_animation_too()
  {
    using (HttpResponseMessage started = await studio.StartAnimation(
             new { scene = "Five balls", settings = new { width = 400, height = 300, samplesPerPixel = 16, threads = 2 }, start = 0.0, end = 100.0, fps = 10.0 }))
      Assert.Equal(HttpStatusCode.Accepted, started.StatusCode);
    using (HttpResponseMessage stop = await studio.Client.PostAsync("/api/stop", null))
      Assert.Equal(HttpStatusCode.NoContent, stop.StatusCode);
    JsonElement done = await studio.PollUntil("/api/animation", a => !a.GetProperty("running").GetBoolean(), "the animation to stop");
    Assert.True(done.GetProperty("framesDone").GetInt32() < done.GetProperty("framesTotal").GetInt32());
  }

  [Fact]
  public async Task Once_stop_shows_idle_a_move_in_the_history_and_an_animation_wait_for_the_stopped_render_instead_of_refusing()
  {
    await studio.RenderAndWait(new { scene = "Five balls", settings = new { width = 16, height = 12 } });
    string marker = Path.Combine(studio.Folder, "sleep-started").Replace("\\", "/", StringComparison.Ordinal);
    string sleepy = await AddScript("Sleepy.cs", StuckScripts.Sleeping(marker, 1500));
    await RenderUntil(sleepy, marker, "the render never reached the script's texture", width: 1, height: 1);
    using (HttpResponseMessage stop = await studio.Client.PostAsync("/api/stop", null))
      Assert.Equal(HttpStatusCode.NoContent, stop.StatusCode);
    Assert.Equal("idle", (await Status()).GetProperty("phase").GetString());

    // The texture still sleeps; the move waits for the stopped render, whose image comes into the history first.
    using (HttpResponseMessage back = await studio.Client.PostAsync("/api/history/back", null))
    {
      Assert.Equal(HttpStatusCode.OK, back.StatusCode);
      JsonElement list = await back.Content.ReadFromJsonAsync<JsonElement>();
      JsonElement[] items = [.. list.GetProperty("items").EnumerateArray()];
      Assert.StartsWith(sleepy, items[^1].GetProperty("label").GetString());
      Assert.False(items[^1].GetProperty("complete").GetBoolean());
      Assert.Equal(items.Length - 2, list.GetProperty("position").GetInt32());
      Assert.StartsWith("Five balls", items[^2].GetProperty("label").GetString());
    }

    File.Delete(marker);
    await RenderUntil(sleepy, marker, "the second render never reached the script's texture", width: 1, height: 1);
    using (HttpResponseMessage stop = await studio.Client.PostAsync("/api/stop", null))
      Assert.Equal(HttpStatusCode.NoContent, stop.StatusCode);
    // Asked once, as the page asks: accepted once the stopped render has ended, not refused while it ends.
    using (HttpResponseMessage started = await studio.StartAnimation(
             new { scene = "Five balls", settings = new { width = 16, height = 12 }, start = 0.0, end = 0.2, fps = 10.0 }))
      Assert.Equal(HttpStatusCode.Accepted, started.StatusCode);
    await studio.PollUntil("/api/animation", a => !a.GetProperty("running").GetBoolean(), "the end of the animation");
  }
}
