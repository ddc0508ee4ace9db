using System;
using System.IO;
using System.Linq;
using System.Net;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text.Json;
using System.Threading;
using System.Threading.Tasks;
using GrCis.Cli;

namespace GrCis.Studio.Tests;

/// <summary>Rendering through the studio: the final image is <c>grcis render</c>'s, byte for byte; probe, errors, scripts.</summary>
public sealed class RenderTests(StudioFixture studio) : IClassFixture<StudioFixture>
{
  Task<JsonElement> RenderAndWait(object body) => studio.RenderAndWait(body);

  [Fact]
  public async Task The_final_image_equals_grcis_renders_png_byte_for_byte()
  {
    await RenderAndWait(new { scene = "Five balls", settings = new { width = 80, height = 60, samplesPerPixel = 4, threads = 2 } });
    byte[] fromStudio = await studio.Client.GetByteArrayAsync("/api/image.png");

    string png = Path.Combine(studio.Folder, "cli.png");
    var output = new StringWriter();
    int code = Program.Run(["render", "Five balls", "--size", "80x60", "--spp", "4", "-t", "2", "-q", "-o", png], output, new StringWriter());
    Assert.Equal(0, code);
    Assert.Equal(File.ReadAllBytes(png), fromStudio);

    byte[] pfm = await studio.Client.GetByteArrayAsync("/api/image.pfm");
    Assert.StartsWith("PF", System.Text.Encoding.ASCII.GetString(pfm, 0, 2));
  }

  [Fact]
  public async Task A_clicked_pixel_gives_its_colour_hash_and_ray_tree()
  {
    await RenderAndWait(new { scene = "Five balls", settings = new { width = 64, height = 48 } });
    JsonElement probe = await studio.Client.GetFromJsonAsync<JsonElement>("/api/probe?x=32&y=24");
    Assert.Equal(3, probe.GetProperty("pixel").GetArrayLength());
    JsonElement root = probe.GetProperty("rays");
    Assert.Equal("Primary", root.GetProperty("kind").GetString());
    Assert.Equal(3, root.GetProperty("origin").GetArrayLength());
    Assert.True(root.GetProperty("children").GetArrayLength() > 0, "a hit on Five balls spawns shadow or secondary rays");
  }

  [Fact]
  public async Task The_ray_view_gets_the_scenes_bounding_boxes_and_its_script_from_the_studio()
  {
    await RenderAndWait(new { scene = "Five balls", settings = new { width = 32, height = 24 } });
    JsonElement boxes = await studio.Client.GetFromJsonAsync<JsonElement>("/api/scene/boxes");
    Assert.True(boxes.GetArrayLength() >= 5, boxes.ToString());   // the five balls at least
    foreach (JsonElement b in boxes.EnumerateArray())
      for (int i = 0; i < 3; i++)
        Assert.True(b.GetProperty("min")[i].GetDouble() <= b.GetProperty("max")[i].GetDouble());
    Assert.Contains("export function rays(", await studio.Client.GetStringAsync("/rays3d.js"));
    Assert.Contains("export class View3d", await studio.Client.GetStringAsync("/view3d.js"));
    Assert.Contains("WebGLRenderer", await studio.Client.GetStringAsync("/vendor/three.min.js"));
  }

  [Fact]
  public async Task The_boxes_come_from_the_renders_own_snapshot_and_are_kept_for_that_render()
  {
    await RenderAndWait(new { scene = "Five balls", settings = new { width = 32, height = 24 } });
    StudioSession session = studio.Server.Session;
    GrCis.Hosting.RenderJob job = session.Controller.LastJob!;
    var raytracer = Assert.IsAssignableFrom<Rendering.RayCasting>(job.ImageFunction);
    Assert.Same(job.Scene.Intersectable, raytracer.LastPrepared!.Source);   // the render kept a snapshot of this scene

    var boxes = session.SceneBoxes()!;
    Assert.Same(boxes, session.SceneBoxes());                                // no second build for the same render
    Assert.Equal(Rendering.Accel.PreparedScene.Prepare(job.Scene.Intersectable).WorldBoxes(), boxes);
  }

  [Fact]
  public async Task A_setting_out_of_range_is_refused_with_its_name()
  {
    using HttpResponseMessage r = await studio.Client.PostAsJsonAsync("/api/render", new { scene = "Five balls", settings = new { width = 0, height = 48 } });
    Assert.Equal(HttpStatusCode.BadRequest, r.StatusCode);
    Assert.Contains("Size 0x48", await r.Content.ReadAsStringAsync());
    using HttpResponseMessage missing = await studio.Client.PostAsJsonAsync("/api/render", new { scene = "No such scene" });
    Assert.Equal(HttpStatusCode.NotFound, missing.StatusCode);
  }

  [Fact]
  public async Task Scripts_of_the_given_folder_are_listed_and_render()
  {
    JsonElement list = await studio.Client.GetFromJsonAsync<JsonElement>("/api/scenes");
    bool found = false;
    foreach (JsonElement s in list.GetProperty("scenes").EnumerateArray())
      found |= s.GetProperty("file").GetString() == "Balls.cs";
    Assert.True(found, list.ToString());
    JsonElement status = await RenderAndWait(new { scene = "Balls", settings = new { width = 32, height = 24 } });
    Assert.True(status.GetProperty("error").ValueKind == JsonValueKind.Null, status.ToString());
    string source = await studio.Client.GetStringAsync("/api/source?scene=Balls");
    Assert.Contains("FiveBalls", source);
  }

  [Fact]
  public async Task Concurrent_render_requests_each_get_their_own_render_id()
  {
    // Released together, so the requests overlap inside the studio rather than queue in the client.
    var go = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
    Task<long>[] posts = [.. Enumerable.Range(0, 50).Select(i => Task.Run(async () =>
    {
      await go.Task;
      using HttpResponseMessage r = await studio.Client.PostAsJsonAsync("/api/render",
        new { scene = "Five balls", settings = new { width = 8 + i % 3, height = 6 } });
      Assert.Equal(HttpStatusCode.Accepted, r.StatusCode);
      return (await r.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("renderId").GetInt64();
    }))];
    go.SetResult();
    long[] ids = await Task.WhenAll(posts);
    Assert.Equal(ids.Length, ids.Distinct().Count());
    // The last one asked for is the one on show, and it finishes.
    JsonElement status = await studio.PollUntil("/api/status",
      s => !s.GetProperty("rendering").GetBoolean() && s.GetProperty("statistics").GetString() is { Length: > 0 }, "the end of the renders");
    Assert.Equal(ids.Max(), status.GetProperty("renderId").GetInt64());
  }

  [Theory]
  [InlineData("{ \"scene\": ")]
  [InlineData("not json")]
  [InlineData("{ \"scene\": 42 }")]
  public async Task Malformed_json_is_a_400_whose_problem_details_say_why(string body)
  {
    using var content = new StringContent(body, System.Text.Encoding.UTF8, "application/json");
    using HttpResponseMessage r = await studio.Client.PostAsync("/api/render", content);
    Assert.Equal(HttpStatusCode.BadRequest, r.StatusCode);
    Assert.Equal("application/problem+json", r.Content.Headers.ContentType?.MediaType);
    JsonElement problem = await r.Content.ReadFromJsonAsync<JsonElement>();
    Assert.Equal(400, problem.GetProperty("status").GetInt32());
    Assert.StartsWith("The request body is not valid JSON for this request: ", problem.GetProperty("detail").GetString());
  }
}
