using System;
using System.IO;
using System.Net;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text.Json;
using System.Threading.Tasks;

namespace GrCis.Studio.Tests;

/// <summary>Animation in the studio: a time range's frames rendered with progress, kept for scrubbing, written into an allowed folder only.</summary>
public sealed class AnimationTests(StudioFixture studio) : IClassFixture<StudioFixture>
{
  [Fact]
  public async Task Frames_of_a_range_are_rendered_kept_for_scrubbing_and_written_to_the_folder()
  {
    string folder = Path.Combine(studio.ScriptsFolder, "frames");
    JsonElement done = await studio.AnimateAndWait(
      new { scene = "Balls", settings = new { width = 32, height = 24 }, start = 0.0, end = 0.4, fps = 10.0, folder });
    int total = done.GetProperty("framesTotal").GetInt32();
    Assert.True(total >= 4, done.ToString());
    Assert.Equal(total, done.GetProperty("framesDone").GetInt32());
    Assert.True(done.GetProperty("error").ValueKind == JsonValueKind.Null, done.ToString());

    byte[] first = await studio.Client.GetByteArrayAsync("/api/animation/frame/0.png");
    Assert.Equal(File.ReadAllBytes(Path.Combine(folder, "out0000.png")), first);
    Assert.Equal(total, Directory.GetFiles(folder, "out*.png").Length);
    using HttpResponseMessage beyond = await studio.Client.GetAsync($"/api/animation/frame/{total}.png");
    Assert.Equal(HttpStatusCode.NotFound, beyond.StatusCode);
  }

  [Fact]
  public async Task Frames_are_not_written_outside_the_given_folders_and_a_bad_range_is_refused()
  {
    using HttpResponseMessage outside = await studio.StartAnimation(
      new { scene = "Balls", start = 0.0, end = 1.0, fps = 10.0, folder = Path.Combine(studio.Folder, "elsewhere") });
    Assert.Equal(HttpStatusCode.Forbidden, outside.StatusCode);
    Assert.False(Directory.Exists(Path.Combine(studio.Folder, "elsewhere")));
    using HttpResponseMessage backwards = await studio.StartAnimation(
      new { scene = "Balls", start = 2.0, end = 1.0, fps = 10.0 });
    Assert.Equal(HttpStatusCode.BadRequest, backwards.StatusCode);
  }

  [Fact]
  public async Task Frames_in_a_folder_are_served_from_their_files_and_without_one_from_memory_with_the_same_bytes()
  {
    string folder = Path.Combine(studio.ScriptsFolder, "served");
    object Body(string? into) => new { scene = "Balls", settings = new { width = 24, height = 18 }, start = 0.0, end = 0.1, fps = 10.0, folder = into };
    await studio.AnimateAndWait(Body(folder));
    byte[] saved = File.ReadAllBytes(Path.Combine(folder, "out0000.png"));
    Assert.Equal(saved, await studio.Client.GetByteArrayAsync("/api/animation/frame/0.png"));
    // The page scrubs through the files themselves: a frame deleted on disk is gone from the page too.
    File.Delete(Path.Combine(folder, "out0001.png"));
    using (HttpResponseMessage gone = await studio.Client.GetAsync("/api/animation/frame/1.png"))
      Assert.Equal(HttpStatusCode.NotFound, gone.StatusCode);

    await studio.AnimateAndWait(Body(null));
    Assert.Equal(saved, await studio.Client.GetByteArrayAsync("/api/animation/frame/0.png"));
  }
}
