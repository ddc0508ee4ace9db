using System.Collections.Generic;
using System.IO;
using System.Net;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text.Json;
using System.Threading.Tasks;
using GrCis.Scripting.Caching;

namespace GrCis.Studio.Tests;

/// <summary>
/// The studio keeps compiled scripts in the compiled-script cache as <c>grcis render</c> does: a studio started
/// later loads an unchanged script from it, and a script edited since is compiled again.
/// </summary>
public sealed class ScriptCacheTests(StudioFixture studio) : IClassFixture<StudioFixture>
{
  [Fact]
  public async Task A_later_studio_loads_an_unchanged_script_from_the_cache_and_compiles_an_edited_one()
  {
    await studio.RenderAndWait(new { scene = "Balls", settings = new { width = 32, height = 24 } });
    Assert.True(studio.Cache.Stores >= 1);

    var cache = new ScriptCache(studio.CacheFolder);
    await using StudioServer later = await StudioServer.StartAsync(
      new StudioOptions { Paths = [studio.ScriptsFolder], ScriptCache = cache }, new List<string>());
    using HttpClient client = StudioFixture.ClientOf(later);
    JsonElement first = await StudioFixture.RenderAndWait(client, new { scene = "Balls", settings = new { width = 32, height = 24 } });
    Assert.True(first.GetProperty("error").ValueKind == JsonValueKind.Null, first.ToString());
    Assert.Equal((1, 0), (cache.Hits, cache.Misses));

    int before = first.GetProperty("version").GetInt32();
    File.WriteAllText(Path.Combine(studio.ScriptsFolder, "Balls.cs"), "Rendering.Scenes.FiveBalls(scene);\n// edited\n");
    using (HttpResponseMessage started = await client.PostAsJsonAsync("/api/render", new { scene = "Balls", settings = new { width = 32, height = 24 } }))
      Assert.Equal(HttpStatusCode.Accepted, started.StatusCode);
    JsonElement edited = await StudioFixture.PollUntil(client, "/api/status",
      st => !st.GetProperty("rendering").GetBoolean() && st.GetProperty("version").GetInt32() > before && cache.Misses > 0, "the edited script's render");
    Assert.True(edited.GetProperty("error").ValueKind == JsonValueKind.Null, edited.ToString());
    Assert.Equal((1, 1, 1), (cache.Hits, cache.Misses, cache.Stores));
  }
}
