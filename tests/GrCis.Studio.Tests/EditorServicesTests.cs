using System.IO;
using System.Linq;
using System.Net;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text.Json;
using System.Threading.Tasks;

namespace GrCis.Studio.Tests;

/// <summary>The editor's language services over HTTP (<c>/api/editor/*</c>): what the page asks while a student types.</summary>
public sealed class EditorServicesTests(StudioFixture studio) : IClassFixture<StudioFixture>
{
  Task<HttpResponseMessage> Ask(string service, object body) => studio.Client.PostAsJsonAsync("/api/editor/" + service, body);

  [Fact]
  public async Task Completion_after_scene_dot_lists_the_scenes_members_and_the_span_they_replace()
  {
    const string text = "scene.Cam";
    using HttpResponseMessage r = await Ask("complete", new { text, position = text.Length, scene = "Balls" });
    Assert.Equal(HttpStatusCode.OK, r.StatusCode);
    JsonElement result = await r.Content.ReadFromJsonAsync<JsonElement>();
    Assert.Equal(6, result.GetProperty("from").GetInt32());
    Assert.Equal(text.Length, result.GetProperty("to").GetInt32());
    JsonElement first = result.GetProperty("items")[0];
    Assert.Equal("Camera", first.GetProperty("label").GetString());
    Assert.Equal("property", first.GetProperty("kind").GetString());
  }

  [Fact]
  public async Task Signature_and_hover_answer_inside_a_call_and_on_a_name_and_nothing_elsewhere()
  {
    const string text = "var m = new PhongMaterial(new double[] { 1, 1, 1 }, ";
    using (HttpResponseMessage r = await Ask("signature", new { text, position = text.Length }))
    {
      JsonElement help = await r.Content.ReadFromJsonAsync<JsonElement>();
      Assert.Equal(1, help.GetProperty("activeParameter").GetInt32());
      Assert.All(help.GetProperty("signatures").EnumerateArray(), s => Assert.StartsWith("PhongMaterial(", s.GetProperty("label").GetString()));
    }
    using (HttpResponseMessage r = await Ask("hover", new { text, position = 14 }))
      Assert.Contains("Phong", (await r.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("text").GetString());
    using (HttpResponseMessage r = await Ask("signature", new { text = "int a = 1; ", position = 11 }))
      Assert.Equal(HttpStatusCode.NoContent, r.StatusCode);
    using (HttpResponseMessage r = await Ask("hover", new { text = "   ", position = 1 }))
      Assert.Equal(HttpStatusCode.NoContent, r.StatusCode);
  }

  [Fact]
  public async Task A_position_outside_the_text_is_a_bad_request_as_problem_details()
  {
    using HttpResponseMessage r = await Ask("complete", new { text = "scene.", position = 99 });
    Assert.Equal(HttpStatusCode.BadRequest, r.StatusCode);
    Assert.Equal("application/problem+json", r.Content.Headers.ContentType?.MediaType);
    Assert.Contains("outside the text", (await r.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("detail").GetString());
  }

  [Fact]
  public async Task A_check_compiles_unsaved_text_as_the_script_and_leaves_the_file_alone()
  {
    string path = Path.Combine(studio.ScriptsFolder, "Balls.cs");
    string before = File.ReadAllText(path);
    const string broken = "// one\nint count = \"many\";\nRendering.Scenes.FiveBalls(scene);\n";
    using (HttpResponseMessage r = await Ask("check", new { text = broken, scene = "Balls" }))
    {
      JsonElement d = Assert.Single((await r.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("diagnostics").EnumerateArray());
      Assert.Equal(2, d.GetProperty("line").GetInt32());
      Assert.Equal(13, d.GetProperty("column").GetInt32());
      Assert.Equal("CS0029", d.GetProperty("id").GetString());
      Assert.Equal("error", d.GetProperty("severity").GetString());
    }
    using (HttpResponseMessage r = await Ask("check", new { text = "Rendering.Scenes.FiveBalls(scene);\n", scene = "Balls" }))
      Assert.Empty((await r.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("diagnostics").EnumerateArray());
    Assert.Equal(before, File.ReadAllText(path));
  }

  [Fact]
  public async Task The_services_are_guarded_as_every_endpoint()
  {
    using HttpResponseMessage r = await studio.Stranger.PostAsJsonAsync("/api/editor/complete", new { text = "scene.", position = 6 });
    Assert.Equal(HttpStatusCode.Unauthorized, r.StatusCode);
  }
}
