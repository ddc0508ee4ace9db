using System;
using System.Collections.Generic;
using System.Linq;
using System.Net;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text.Json;
using System.Threading.Tasks;

namespace GrCis.Studio.Tests;

/// <summary>
/// <c>GET /api/scene/tessellation</c>, what the page's 3D view draws: the render's solids (shapes shared), lights and camera
/// in GrCis's world, an animation frame's scene, and a sentence, not an empty scene, before anything is rendered.
/// </summary>
public sealed class Scene3dApiTests(StudioFixture studio) : IClassFixture<StudioFixture>
{
  [Fact]
  public async Task The_rendered_scene_comes_as_its_solids_one_shared_sphere_its_light_and_its_camera()
  {
    await studio.RenderAndWait(new { scene = "Five balls", settings = new { width = 40, height = 30 } });
    JsonElement scene = await studio.Client.GetFromJsonAsync<JsonElement>("/api/scene/tessellation");

    Assert.Equal((40, 30), (scene.GetProperty("width").GetInt32(), scene.GetProperty("height").GetInt32()));
    JsonElement[] parts = scene.GetProperty("parts").EnumerateArray().ToArray();
    Assert.Equal(5, parts.Length);
    Assert.All(parts, p => Assert.Equal(("Sphere", "Surface", 0),
                                        (p.GetProperty("type").GetString(), p.GetProperty("kind").GetString(), p.GetProperty("shape").GetInt32())));
    // The five balls share one UV sphere: 49 × 25 vertices, 2 × 48 × 23 triangles (the poles' rows are single triangles).
    JsonElement sphere = Assert.Single(scene.GetProperty("shapes").EnumerateArray());
    Assert.Equal(0, sphere.GetProperty("positions").GetArrayLength() % 3);
    Assert.True(sphere.GetProperty("indices").GetArrayLength() > 1000);
    // The second ball stands at x = -2.2 (row vectors: the translation is the matrix's last row).
    double[] matrix = parts[1].GetProperty("matrix").EnumerateArray().Select(e => e.GetDouble()).ToArray();
    Assert.Equal(16, matrix.Length);
    Assert.Equal(-2.2, matrix[12], 9);
    Assert.Equal([0.2, 0.9, 0.5], parts[1].GetProperty("color").EnumerateArray().Select(e => e.GetDouble()));

    JsonElement light = Assert.Single(scene.GetProperty("lights").EnumerateArray());
    Assert.Equal("Point", light.GetProperty("kind").GetString());
    Assert.Equal([-5.0, 3.0, -3.0], light.GetProperty("position").EnumerateArray().Select(e => e.GetDouble()));
    JsonElement camera = scene.GetProperty("camera");
    Assert.Equal([0.0, 0.0, -10.0], camera.GetProperty("position").EnumerateArray().Select(e => e.GetDouble()));
    Assert.Equal(40.0 / 30.0, camera.GetProperty("aspect").GetDouble(), 9);
    // GrCis's 60° is the horizontal angle: vertically, 2 atan(tan 30° · 30/40).
    Assert.Equal(2 * Math.Atan(Math.Tan(Math.PI / 6) * 30 / 40), camera.GetProperty("verticalFov").GetDouble(), 6);
    Assert.True(camera.GetProperty("exact").GetBoolean());
    // Behind the token, as every other endpoint.
    using HttpResponseMessage stranger = await studio.Stranger.GetAsync("/api/scene/tessellation");
    Assert.Equal(HttpStatusCode.Unauthorized, stranger.StatusCode);
  }

  [Fact]
  public async Task An_animation_frames_scene_comes_at_the_frames_time_and_a_frame_beyond_the_range_is_a_sentence()
  {
    JsonElement done = await studio.AnimateAndWait(new { scene = "Balls", settings = new { width = 24, height = 18 }, start = 0.0, end = 0.2, fps = 10.0 });
    int total = done.GetProperty("framesTotal").GetInt32();

    JsonElement frame = await studio.Client.GetFromJsonAsync<JsonElement>("/api/scene/tessellation?frame=1");
    Assert.Equal(5, frame.GetProperty("parts").GetArrayLength());
    Assert.EndsWith("frame 1", frame.GetProperty("name").GetString());
    using HttpResponseMessage beyond = await studio.Client.GetAsync($"/api/scene/tessellation?frame={total}");
    Assert.Equal(HttpStatusCode.NotFound, beyond.StatusCode);
    Assert.Contains($"no frame {total}", await beyond.Content.ReadAsStringAsync());
  }

  [Fact]
  public async Task CSG_operands_are_named_by_their_operation_a_scripts_own_solid_is_its_box_and_a_sphere_light_has_its_radius()
  {
    string path = System.IO.Path.Combine(studio.ScriptsFolder, "Hole.cs");
    System.IO.File.WriteAllText(path, """
      CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
      root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
      root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 0.5, 0.5, 0.5 }, 0.1, 0.6, 0.3, 16));
      scene.Intersectable = root;
      scene.BackgroundColor = new double[] { 0.0, 0.0, 0.0 };
      scene.Camera = new StaticCamera(new Vector3d(0.0, 0.0, -10.0), new Vector3d(0.0, 0.0, 1.0), 60.0);
      scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
      scene.Sources.Add(new SphereLightSource(new Vector3d(-2.0, 4.0, -1.0), 0.5, 1.0));
      CSGInnerNode hole = new CSGInnerNode(SetOperation.Difference);
      hole.InsertChild(new Cube(), Matrix4d.Identity);
      hole.InsertChild(new Sphere(), Matrix4d.Scale(0.6));
      root.InsertChild(hole, Matrix4d.Identity);
      root.InsertChild(new Blob(), Matrix4d.CreateTranslation(3.0, 0.0, 0.0));

      class Blob : DefaultSceneNode, ISolid
      {
        public void GetBoundingBox(out Vector3d c1, out Vector3d c2) { c1 = new Vector3d(-1.0, -1.0, -1.0); c2 = new Vector3d(1.0, 1.0, 1.0); }
      }
      """);
    string name;
    using (HttpResponseMessage added = await studio.Client.PostAsJsonAsync("/api/scenes/add", new { path }))
      name = (await added.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("name").GetString()!;
    await studio.RenderAndWait(new { scene = name, settings = new { width = 32, height = 24 } });
    JsonElement scene = await studio.Client.GetFromJsonAsync<JsonElement>("/api/scene/tessellation");

    var parts = scene.GetProperty("parts").EnumerateArray()
      .Select(p => (Type: p.GetProperty("type").GetString(), Kind: p.GetProperty("kind").GetString(), Csg: p.GetProperty("csg").GetString())).ToArray();
    Assert.Equal([("Cube", "Surface", "Difference"), ("Sphere", "Surface", "Difference"), ("Blob", "BoundingBox", null)], parts);
    JsonElement light = Assert.Single(scene.GetProperty("lights").EnumerateArray());
    Assert.Equal(("Sphere", 0.5), (light.GetProperty("kind").GetString(), light.GetProperty("radius").GetDouble()));
    Assert.Contains(scene.GetProperty("notes").EnumerateArray(), n => n.GetString()!.Contains("Blob", StringComparison.Ordinal));
  }

  [Fact]
  public async Task Before_any_render_the_answer_says_to_render_first()
  {
    await using StudioServer fresh = await StudioServer.StartAsync(new StudioOptions { Paths = [studio.ScriptsFolder] }, new List<string>());
    using HttpClient client = StudioFixture.ClientOf(fresh);
    using HttpResponseMessage answer = await client.GetAsync("/api/scene/tessellation");
    Assert.Equal(HttpStatusCode.NotFound, answer.StatusCode);
    Assert.Equal("application/problem+json", answer.Content.Headers.ContentType?.MediaType);
    JsonElement problem = await answer.Content.ReadFromJsonAsync<JsonElement>();
    Assert.Equal("nothing rendered yet: render a scene, and its scene shows in 3D", problem.GetProperty("detail").GetString());
    // And the points the render's rays hit.
    using HttpResponseMessage points = await client.GetAsync("/api/scene/points");
    Assert.Equal(HttpStatusCode.NotFound, points.StatusCode);
    Assert.Equal("nothing rendered yet: render a scene, and the points its rays hit show in 3D",
                 (await points.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("detail").GetString());
  }
}
