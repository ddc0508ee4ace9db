using System.IO;
using System.Net;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text.Json;
using System.Threading.Tasks;

namespace GrCis.Studio.Tests;

/// <summary>
/// Honest settings in the studio's API: a chosen scene's own values for the fields (size, samples, algorithm, range),
/// and the one precedence rule for a render and an animation: the settings the page names as given win, the others
/// are the script's where it sets them.
/// </summary>
public sealed class ScriptValuesTests(StudioFixture studio) : IClassFixture<StudioFixture>
{
  const string Script = """
    Rendering.Scenes.FiveBalls(scene);
    context[PropertyName.CTX_WIDTH] = 40;
    context[PropertyName.CTX_HEIGHT] = 30;
    context[PropertyName.CTX_SUPERSAMPLING] = 4;
    context[PropertyName.CTX_ALGORITHM] = new DistributedRayTracing();
    context[PropertyName.CTX_START_ANIM] = 0.0;
    context[PropertyName.CTX_END_ANIM] = 0.5;
    context[PropertyName.CTX_FPS] = 4.0;
    context[PropertyName.CTX_TOOLTIP] = "no parameters";
    """;

  async Task<string> AddScript()
  {
    string path = Path.Combine(studio.ScriptsFolder, "Own.cs");
    File.WriteAllText(path, Script);
    using HttpResponseMessage added = await studio.Client.PostAsJsonAsync("/api/scenes/add", new { path });
    Assert.Equal(HttpStatusCode.OK, added.StatusCode);
    return (await added.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("name").GetString()!;
  }

  static object Settings => new { width = 24, height = 18, samplesPerPixel = 1, threads = 2 };

  [Fact]
  public async Task A_chosen_scene_gives_the_scripts_own_values_and_a_built_in_scene_none()
  {
    string name = await AddScript();
    using HttpResponseMessage r = await studio.Client.PostAsJsonAsync("/api/scene/values", new { scene = name });
    Assert.Equal(HttpStatusCode.OK, r.StatusCode);
    JsonElement v = await r.Content.ReadFromJsonAsync<JsonElement>();
    Assert.Equal((40, 30, 4), (v.GetProperty("width").GetInt32(), v.GetProperty("height").GetInt32(), v.GetProperty("samplesPerPixel").GetInt32()));
    Assert.Equal("DistributedRayTracing", v.GetProperty("algorithm").GetString());
    Assert.Equal((0.0, 0.5, 4.0), (v.GetProperty("start").GetDouble(), v.GetProperty("end").GetDouble(), v.GetProperty("fps").GetDouble()));
    Assert.Equal("no parameters", v.GetProperty("tooltip").GetString());

    JsonElement none = await (await studio.Client.PostAsJsonAsync("/api/scene/values", new { scene = "Five balls" })).Content.ReadFromJsonAsync<JsonElement>();
    Assert.Equal(JsonValueKind.Null, none.GetProperty("width").ValueKind);
    Assert.Equal(JsonValueKind.Null, none.GetProperty("algorithm").ValueKind);
  }

  [Fact]
  public async Task A_script_that_does_not_compile_gives_its_errors_for_the_values()
  {
    string path = Path.Combine(studio.ScriptsFolder, "Broken.cs");
    File.WriteAllText(path, "scene.NoSuchThing = 1;\n");
    using HttpResponseMessage added = await studio.Client.PostAsJsonAsync("/api/scenes/add", new { path });
    string name = (await added.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("name").GetString()!;
    using HttpResponseMessage r = await studio.Client.PostAsJsonAsync("/api/scene/values", new { scene = name });
    Assert.Equal(HttpStatusCode.BadRequest, r.StatusCode);
    JsonElement body = await r.Content.ReadFromJsonAsync<JsonElement>();
    Assert.Contains("Broken.cs", body.GetProperty("detail").GetString());
    Assert.Equal(1, body.GetProperty("diagnostics")[0].GetProperty("line").GetInt32());
  }

  [Fact]
  public async Task The_given_settings_win_and_the_others_are_the_scripts()
  {
    string name = await AddScript();
    JsonElement scripts = await studio.RenderAndWait(new { scene = name, settings = Settings });
    Assert.Equal((40, 30, 4), (scripts.GetProperty("width").GetInt32(), scripts.GetProperty("height").GetInt32(), scripts.GetProperty("samplesPerPixel").GetInt32()));

    JsonElement sized = await studio.RenderAndWait(new { scene = name, settings = Settings, given = new[] { "Size" } });
    Assert.Equal((24, 18, 4), (sized.GetProperty("width").GetInt32(), sized.GetProperty("height").GetInt32(), sized.GetProperty("samplesPerPixel").GetInt32()));

    JsonElement both = await studio.RenderAndWait(new { scene = name, settings = Settings, given = new[] { "Size", "samplesPerPixel" } });
    Assert.Equal(1, both.GetProperty("samplesPerPixel").GetInt32());
    JsonElement history = await studio.Client.GetFromJsonAsync<JsonElement>("/api/history");
    JsonElement current = history.GetProperty("items")[history.GetProperty("position").GetInt32()];
    Assert.StartsWith(name, current.GetProperty("label").GetString());
    Assert.Contains("24x18, 1 spp", current.GetProperty("label").GetString());

    using HttpResponseMessage bad = await studio.Client.PostAsJsonAsync("/api/render", new { scene = name, settings = Settings, given = new[] { "Colour" } });
    Assert.Equal(HttpStatusCode.BadRequest, bad.StatusCode);
    Assert.Contains("Colour", await bad.Content.ReadAsStringAsync());
  }

  [Fact]
  public async Task An_animation_takes_the_range_the_page_gives_else_the_scripts()
  {
    string name = await AddScript();
    async Task<int> Frames(double? start, double? end, double? fps)
    {
      JsonElement done = await studio.AnimateAndWait(
        new { scene = name, settings = Settings, given = new[] { "Size", "SamplesPerPixel" }, start, end, fps });
      return done.GetProperty("framesTotal").GetInt32();
    }
    Assert.Equal(3, await Frames(null, null, null));     // the script's 0–0.5 s at 4 fps
    Assert.Equal(2, await Frames(0.0, 0.25, null));      // the page's range at the script's rate
    Assert.Equal(5, await Frames(null, null, 8.0));      // the script's range at the page's rate
  }
}
