using System;
using System.Collections.Generic;
using System.IO;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text.Json;
using System.Threading.Tasks;

namespace GrCis.Studio.Tests;

/// <summary>
/// The editor's language services load in the background when the studio starts (<see cref="StudioOptions.WarmEditor"/>,
/// on in <c>grcis studio</c>; issue 39), so the page's first completion does not pay their seconds of loading.
/// </summary>
public sealed class EditorWarmUpTests
{
  [Fact]
  public async Task The_language_services_load_when_the_studio_starts_without_a_request()
  {
    DirectoryInfo folder = Directory.CreateTempSubdirectory("grcis-studio-warm-");
    try
    {
      File.WriteAllText(Path.Combine(folder.FullName, "FiveBalls.cs"), "Rendering.Scenes.FiveBalls(scene);\n");
      await using StudioServer server = await StudioServer.StartAsync(new StudioOptions { Paths = [folder.FullName], WarmEditor = true }, new List<string>());
      Task warmed = Assert.IsAssignableFrom<Task>(server.Editor.Warmed);
      await warmed.WaitAsync(TimeSpan.FromMinutes(3));
      Assert.True(warmed.IsCompletedSuccessfully);
      Assert.True(server.Editor.Loaded);

      // The page's completion is then answered by the loaded services.
      using HttpClient client = StudioFixture.ClientOf(server);
      const string source = "scene.";
      using HttpResponseMessage answer = await client.PostAsJsonAsync("/api/editor/complete", new { text = source, position = source.Length, scene = "FiveBalls" });
      answer.EnsureSuccessStatusCode();
      JsonElement items = (await answer.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("items");
      Assert.True(items.GetArrayLength() > 0);
    }
    finally
    {
      folder.Delete(recursive: true);
    }
  }

  [Fact]
  public async Task A_studio_told_not_to_warm_loads_nothing_until_asked()
  {
    await using StudioServer server = await StudioServer.StartAsync(new StudioOptions { NoDefault = true }, new List<string>());
    Assert.Null(server.Editor.Warmed);
    Assert.False(server.Editor.Loaded);
  }

  [Fact]
  public async Task Asked_not_to_wait_a_cold_studio_answers_503_at_once_and_starts_loading()
  {
    await using StudioServer server = await StudioServer.StartAsync(new StudioOptions { NoDefault = true }, new List<string>());
    using HttpClient client = StudioFixture.ClientOf(server);
    using HttpResponseMessage loading = await client.GetAsync("/api/editor/ready?wait=false");
    Assert.Equal(System.Net.HttpStatusCode.ServiceUnavailable, loading.StatusCode);
    Assert.NotNull(loading.Headers.RetryAfter);
    Task warmed = Assert.IsAssignableFrom<Task>(server.Editor.Warmed);
    Assert.True(await server.EditorReadyAsync(TimeSpan.FromMinutes(3), default));
    Assert.True(warmed.IsCompletedSuccessfully);
    using HttpResponseMessage loaded = await client.GetAsync("/api/editor/ready?wait=false");
    Assert.Equal(System.Net.HttpStatusCode.NoContent, loaded.StatusCode);
  }

  [Fact]
  public async Task The_ready_request_loads_the_services_of_a_cold_studio_and_answers_once_they_are_loaded()
  {
    await using StudioServer server = await StudioServer.StartAsync(new StudioOptions { NoDefault = true }, new List<string>());
    Assert.Null(server.Editor.Warmed);
    using HttpClient client = StudioFixture.ClientOf(server);
    using HttpResponseMessage ready = await client.GetAsync("/api/editor/ready");
    Assert.Equal(System.Net.HttpStatusCode.NoContent, ready.StatusCode);
    Task warmed = Assert.IsAssignableFrom<Task>(server.Editor.Warmed);
    Assert.True(warmed.IsCompletedSuccessfully);
    Assert.True(server.Editor.Loaded);

    // A second page's request finds them ready and starts nothing new.
    using HttpResponseMessage again = await client.GetAsync("/api/editor/ready");
    Assert.Equal(System.Net.HttpStatusCode.NoContent, again.StatusCode);
    Assert.Same(warmed, server.Editor.Warmed);
  }
}
