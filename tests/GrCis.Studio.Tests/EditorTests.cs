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
