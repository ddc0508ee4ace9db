using System;
using System.Linq;
using System.Net;
using System.Net.Http;
using System.Net.Http.Json;
using System.Numerics;
using System.Text.Json;
using System.Threading.Tasks;
using SharpGLTF.Schema2;

namespace GrCis.Studio.Tests;

/// <summary>The scene on show as glTF (<c>/api/scene.glb</c>, an animation frame's <c>.glb</c>): what <c>grcis export</c> writes, behind the token and Origin rules.</summary>
public sealed class SceneFileTests(StudioFixture studio) : IClassFixture<StudioFixture>
{
  [Fact]
  public async Task The_rendered_scene_downloads_as_glb_with_its_solids_camera_and_light()
  {
    await studio.RenderAndWait(new { scene = "Five balls", settings = new { width = 40, height = 30 } });
    using HttpResponseMessage response = await studio.Client.GetAsync("/api/scene.glb");

    Assert.Equal(HttpStatusCode.OK, response.StatusCode);
    Assert.Equal("model/gltf-binary", response.Content.Headers.ContentType?.MediaType);
    Assert.Equal("scene.glb", response.Content.Headers.ContentDisposition?.FileNameStar ?? response.Content.Headers.ContentDisposition?.FileName);
    byte[] glb = await response.Content.ReadAsByteArrayAsync();
    ModelRoot model = ModelRoot.ParseGLB(glb);
    Assert.Equal(5, model.LogicalNodes.Count(n => n.Mesh != null));
    Assert.Single(model.LogicalNodes, n => n.PunctualLight != null);
    Node camera = Assert.Single(model.LogicalNodes, n => n.Camera != null);
    // The render's size sets the aspect ratio; the camera stands where the scene's does (z mirrored into glTF).
    var perspective = (CameraPerspective)camera.Camera.Settings;
    Assert.Equal(40.0 / 30.0, perspective.AspectRatio!.Value, 5);
    var expected = (Rendering.StaticCamera)Rendering.Scenes.Create("Five balls").Camera!;
    Vector3 at = camera.WorldMatrix.Translation;
    Assert.True(Math.Abs(at.X - expected.center.X) < 1e-4 && Math.Abs(at.Y - expected.center.Y) < 1e-4 && Math.Abs(at.Z + expected.center.Z) < 1e-4, at.ToString());
    Assert.Contains("api/scene.glb", await studio.Client.GetStringAsync("/"));
  }

  [Fact]
  public async Task The_glb_needs_the_token_and_the_studios_own_origin()
  {
    await studio.RenderAndWait(new { scene = "Five balls", settings = new { width = 16, height = 12 } });
    using HttpResponseMessage noToken = await studio.Stranger.GetAsync("/api/scene.glb");
    Assert.Equal(HttpStatusCode.Unauthorized, noToken.StatusCode);
    using var crossSite = new HttpRequestMessage(HttpMethod.Get, "/api/scene.glb");
    crossSite.Headers.Add(AccessGuard.HeaderName, studio.Server.Token);
    crossSite.Headers.Add("Origin", "http://evil.example");
    using HttpResponseMessage refused = await studio.Stranger.SendAsync(crossSite);
    Assert.Equal(HttpStatusCode.Forbidden, refused.StatusCode);
  }

  [Fact]
  public async Task An_animation_frames_scene_downloads_as_glb_and_a_frame_beyond_the_range_is_not_found()
  {
    JsonElement done = await studio.AnimateAndWait(new { scene = "Balls", settings = new { width = 24, height = 18 }, start = 0.0, end = 0.2, fps = 10.0 });
    int total = done.GetProperty("framesTotal").GetInt32();

    ModelRoot frame = ModelRoot.ParseGLB(await studio.Client.GetByteArrayAsync("/api/animation/frame/1.glb"));
    Assert.Equal(5, frame.LogicalNodes.Count(n => n.Mesh != null));
    Assert.Equal(24.0 / 18.0, ((CameraPerspective)frame.LogicalNodes.Single(n => n.Camera != null).Camera.Settings).AspectRatio!.Value, 5);
    using HttpResponseMessage beyond = await studio.Client.GetAsync($"/api/animation/frame/{total}.glb");
    Assert.Equal(HttpStatusCode.NotFound, beyond.StatusCode);
  }
}
