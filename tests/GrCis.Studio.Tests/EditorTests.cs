using System;
using System.IO;
using System.Net;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text;
using System.Text.Json;
using System.Threading.Tasks;

namespace GrCis.Studio.Tests;

/// <summary>Editing a script in the page: save → compile → diagnostics at line and column → re-render; saves by other editors re-render too.</summary>
public sealed class EditorTests(StudioFixture studio) : IClassFixture<StudioFixture>
{
  const string Good = "Rendering.Scenes.FiveBalls(scene);\n";

  Task<JsonElement> WaitFor(Func<JsonElement, bool> done) => studio.PollUntil("/api/status", done, "the expected status");

  Task<HttpResponseMessage> Save(string text) =>
    studio.Client.PutAsync("/api/source?scene=Balls", new StringContent(text, Encoding.UTF8, "text/plain"));

  [Fact]
  public async Task A_saved_typo_is_shown_at_its_line_and_column_and_the_fix_renders_a_new_image()
  {
    await studio.RenderAndWait(new { scene = "Balls", settings = new { width = 32, height = 24 } });
    int before = (await studio.Client.GetFromJsonAsync<JsonElement>("/api/status")).GetProperty("version").GetInt32();

    using (HttpResponseMessage saved = await Save("// a comment line\nRendering.Scenes.FiveBals(scene);\n"))
      Assert.Equal(HttpStatusCode.NoContent, saved.StatusCode);
    JsonElement failed = await WaitFor(s => s.GetProperty("diagnostics").GetArrayLength() > 0);
    JsonElement d = failed.GetProperty("diagnostics")[0];
    Assert.Equal(2, d.GetProperty("line").GetInt32());
    Assert.Equal(18, d.GetProperty("column").GetInt32());
    Assert.Equal("CS0117", d.GetProperty("id").GetString());
    Assert.Contains("FiveBals", d.GetProperty("message").GetString());

    using (HttpResponseMessage fixedSave = await Save(Good))
      Assert.Equal(HttpStatusCode.NoContent, fixedSave.StatusCode);
    JsonElement rendered = await WaitFor(s => !s.GetProperty("rendering").GetBoolean() && s.GetProperty("version").GetInt32() > before &&
                                             s.GetProperty("diagnostics").GetArrayLength() == 0 && s.GetProperty("statistics").GetString()!.Length > 0);
    Assert.True(rendered.GetProperty("error").ValueKind == JsonValueKind.Null, rendered.ToString());
    Assert.Equal(Good, File.ReadAllText(Path.Combine(studio.ScriptsFolder, "Balls.cs")));
  }

  [Fact]
  public async Task A_saved_script_that_throws_is_marked_at_the_line_that_threw()
  {
    await studio.RenderAndWait(new { scene = "Balls", settings = new { width = 32, height = 24 } });
    using (HttpResponseMessage saved = await Save("Rendering.Scenes.FiveBalls(scene);\n\nthrow new System.InvalidOperationException(\"not yet\");\n"))
      Assert.Equal(HttpStatusCode.NoContent, saved.StatusCode);
    JsonElement failed = await WaitFor(s => s.GetProperty("diagnostics").GetArrayLength() > 0);
    JsonElement d = Assert.Single(failed.GetProperty("diagnostics").EnumerateArray());
    Assert.Equal(3, d.GetProperty("line").GetInt32());
    Assert.Equal("InvalidOperationException", d.GetProperty("id").GetString());
    Assert.Equal("not yet", d.GetProperty("message").GetString());
    Assert.Contains("runtime error", failed.GetProperty("error").GetString());

    using (HttpResponseMessage fixedSave = await Save(Good))
      Assert.Equal(HttpStatusCode.NoContent, fixedSave.StatusCode);
    await WaitFor(s => !s.GetProperty("rendering").GetBoolean() && s.GetProperty("diagnostics").GetArrayLength() == 0 &&
                       s.GetProperty("error").ValueKind == JsonValueKind.Null);
  }

  async Task<string> AddScript(string file, string text)
  {
    string path = Path.Combine(studio.ScriptsFolder, file);
    File.WriteAllText(path, text);
    using HttpResponseMessage added = await studio.Client.PostAsJsonAsync("/api/scenes/add", new { path });
    Assert.Equal(HttpStatusCode.OK, added.StatusCode);
    return (await added.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("name").GetString()!;
  }

  Task<HttpResponseMessage> SaveScene(string scene, string text) =>
    studio.Client.PutAsync("/api/source?scene=" + Uri.EscapeDataString(scene), new StringContent(text, Encoding.UTF8, "text/plain"));

  [Fact]
  public async Task Saving_a_script_that_is_not_the_rendered_one_compiles_it_and_shows_its_diagnostics()
  {
    await studio.RenderAndWait(new { scene = "Balls", settings = new { width = 32, height = 24 } });
    string other = await AddScript("Other.cs", Good);

    using (HttpResponseMessage saved = await SaveScene(other, "// first\n// second\nRendering.Scenes.Flagz(scene);\n"))
      Assert.Equal(HttpStatusCode.Accepted, saved.StatusCode);
    JsonElement failed = await WaitFor(s => s.GetProperty("phase").GetString() == "idle");
    JsonElement d = Assert.Single(failed.GetProperty("diagnostics").EnumerateArray());
    Assert.Equal(3, d.GetProperty("line").GetInt32());
    Assert.Equal("CS0117", d.GetProperty("id").GetString());
    Assert.Contains("Other.cs", failed.GetProperty("error").GetString());

    using (HttpResponseMessage fixedSave = await SaveScene(other, Good))
      Assert.Equal(HttpStatusCode.Accepted, fixedSave.StatusCode);
    JsonElement compiled = await WaitFor(s => s.GetProperty("phase").GetString() == "idle");
    Assert.Equal(0, compiled.GetProperty("diagnostics").GetArrayLength());
    Assert.Equal(JsonValueKind.Null, compiled.GetProperty("error").ValueKind);
    // Balls is still the rendered scene: the compile did not replace it.
    Assert.Equal("Balls", (await studio.Client.GetFromJsonAsync<JsonElement>("/api/scenes")).GetProperty("selected").GetString());
  }

  [Fact]
  public async Task A_saved_script_being_compiled_shows_compiling_and_stop_ends_it()
  {
    await studio.RenderAndWait(new { scene = "Balls", settings = new { width = 32, height = 24 } });
    string marker = Path.Combine(studio.Folder, "stuck-save").Replace("\\", "/", StringComparison.Ordinal);
    string stuck = await AddScript("StuckSave.cs", Good);
    using (HttpResponseMessage saved = await SaveScene(stuck, GrCis.TestSupport.StuckScripts.WhileBuilding(marker)))
      Assert.Equal(HttpStatusCode.Accepted, saved.StatusCode);
    DateTime deadline = DateTime.UtcNow + TimeSpan.FromMinutes(1);
    while (!File.Exists(marker))
    {
      Assert.True(DateTime.UtcNow < deadline, "the saved script never ran");
      await Task.Delay(20);
    }
    Assert.Equal("compiling", (await studio.Client.GetFromJsonAsync<JsonElement>("/api/status")).GetProperty("phase").GetString());
    using (HttpResponseMessage stop = await studio.Client.PostAsync("/api/stop", null))
      Assert.Equal(HttpStatusCode.NoContent, stop.StatusCode);
    JsonElement stopped = await studio.Client.GetFromJsonAsync<JsonElement>("/api/status");
    Assert.Equal("idle", stopped.GetProperty("phase").GetString());
    Assert.Equal(JsonValueKind.Null, stopped.GetProperty("error").ValueKind);
  }

  [Fact]
  public async Task The_editor_learns_of_a_change_on_disk_and_its_save_never_replaces_a_text_it_has_not_seen()
  {
    string file = Path.Combine(studio.ScriptsFolder, "Balls.cs");
    File.WriteAllText(file, Good);
    using HttpResponseMessage loaded = await studio.Client.GetAsync("/api/source?scene=Balls");
    string loadedTag = loaded.Headers.ETag!.Tag;
    using (var same = new HttpRequestMessage(HttpMethod.Get, "/api/source?scene=Balls"))
    {
      same.Headers.TryAddWithoutValidation("If-None-Match", loadedTag);
      using HttpResponseMessage unchanged = await studio.Client.SendAsync(same);
      Assert.Equal(HttpStatusCode.NotModified, unchanged.StatusCode);
    }

    const string Outside = "// changed by another editor\nRendering.Scenes.FiveBalls(scene);\n";
    File.WriteAllText(file, Outside);
    string diskTag;
    using (var again = new HttpRequestMessage(HttpMethod.Get, "/api/source?scene=Balls"))
    {
      again.Headers.TryAddWithoutValidation("If-None-Match", loadedTag);
      using HttpResponseMessage changed = await studio.Client.SendAsync(again);
      Assert.Equal(HttpStatusCode.OK, changed.StatusCode);
      Assert.Equal(Outside, await changed.Content.ReadAsStringAsync());
      diskTag = changed.Headers.ETag!.Tag;
      Assert.NotEqual(loadedTag, diskTag);
    }

    // A save from the text loaded before the change is refused, and the file keeps the other editor's text.
    HttpRequestMessage Put(string tag) => new(HttpMethod.Put, "/api/source?scene=Balls")
    {
      Content = new StringContent(Good, Encoding.UTF8, "text/plain"),
      Headers = { { "If-Match", tag } },
    };
    using (HttpResponseMessage stale = await studio.Client.SendAsync(Put(loadedTag)))
    {
      Assert.Equal(HttpStatusCode.PreconditionFailed, stale.StatusCode);
      Assert.Contains("changed on disk", await stale.Content.ReadAsStringAsync());
    }
    Assert.Equal(Outside, File.ReadAllText(file));

    // From the disk's text (reloaded, or kept knowingly) it saves, and answers the new version.
    using HttpResponseMessage saved = await studio.Client.SendAsync(Put(diskTag));
    Assert.True(saved.IsSuccessStatusCode, saved.StatusCode.ToString());
    Assert.Equal(Good, File.ReadAllText(file));
    using HttpResponseMessage now = await studio.Client.GetAsync("/api/source?scene=Balls");
    Assert.Equal(now.Headers.ETag!.Tag, saved.Headers.ETag!.Tag);
  }

  [Fact]
  public async Task A_save_by_another_editor_re_renders()
  {
    await studio.RenderAndWait(new { scene = "Balls", settings = new { width = 32, height = 24 } });
    int before = (await studio.Client.GetFromJsonAsync<JsonElement>("/api/status")).GetProperty("version").GetInt32();
    File.WriteAllText(Path.Combine(studio.ScriptsFolder, "Balls.cs"), "Rendering.Scenes.Flags(scene);\n");
    await WaitFor(s => !s.GetProperty("rendering").GetBoolean() && s.GetProperty("version").GetInt32() > before &&
                       s.GetProperty("statistics").GetString()!.Length > 0);
    File.WriteAllText(Path.Combine(studio.ScriptsFolder, "Balls.cs"), Good);
  }

  [Fact]
  public async Task The_editor_is_served_from_the_studio_itself()
  {
    string page = await studio.Client.GetStringAsync("/");
    Assert.Contains("vendor/codemirror.js", page);
    Assert.DoesNotContain("https://", page);
    string editor = await studio.Client.GetStringAsync("/vendor/codemirror.js");
    Assert.Contains("CodeMirror", editor);
    Assert.Contains("text/x-csharp", await studio.Client.GetStringAsync("/vendor/clike.js"));
    using HttpResponseMessage none = await studio.Client.GetAsync("/vendor/jquery.js");
    Assert.Equal(HttpStatusCode.NotFound, none.StatusCode);
  }
}
