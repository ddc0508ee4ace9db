using System;
using System.Collections.Generic;
using System.IO;
using System.Net;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text;
using System.Text.Json;
using System.Threading.Tasks;

namespace GrCis.Studio.Tests;

/// <summary>
/// Links inside the given folders: one that leads out (a linked folder, a file linked to /etc/passwd) is neither listed,
/// read nor written, by any endpoint; one that stays inside works and is written through. Unix only (links on
/// Windows need privileges).
/// </summary>
public sealed class SymlinkTests : IAsyncLifetime
{
  readonly string root = Directory.CreateTempSubdirectory("grcis-links-").FullName;
  StudioServer server = null!;
  HttpClient client = null!;

  string Allowed => Path.Combine(root, "allowed");

  string Outside => Path.Combine(root, "outside");

  public async Task InitializeAsync()
  {
    if (OperatingSystem.IsWindows())
      return;
    Directory.CreateDirectory(Allowed);
    Directory.CreateDirectory(Outside);
    File.WriteAllText(Path.Combine(Allowed, "Good.cs"), "Rendering.Scenes.FiveBalls(scene);\n");
    File.WriteAllText(Path.Combine(Allowed, "Swapped.cs"), "Rendering.Scenes.Flags(scene);\n");
    File.WriteAllText(Path.Combine(Outside, "Secret.cs"), "// outside the studio's folders\nRendering.Scenes.Flags(scene);\n");
    File.WriteAllText(Path.Combine(Outside, "secret.txt"), "not for the studio");
    Directory.CreateSymbolicLink(Path.Combine(Allowed, "linked"), Outside);             // a folder leading out
    File.CreateSymbolicLink(Path.Combine(Allowed, "Passwd.cs"), "/etc/passwd");        // a file leading out
    File.CreateSymbolicLink(Path.Combine(Allowed, "Alias.cs"), "Good.cs");             // a relative link that stays inside
    server = await StudioServer.StartAsync(new StudioOptions { Paths = [Allowed], NoDefault = true }, new List<string>());
    client = new HttpClient { BaseAddress = new Uri(new Uri(server.Url).GetLeftPart(UriPartial.Authority)) };
    client.DefaultRequestHeaders.Add(AccessGuard.HeaderName, server.Token);
  }

  public async Task DisposeAsync()
  {
    if (OperatingSystem.IsWindows())
      return;
    client.Dispose();
    await server.DisposeAsync();
    Directory.Delete(root, recursive: true);
  }

  static string Q(string path) => Uri.EscapeDataString(path);

  [SkippableFact]
  public async Task A_linked_folder_leading_out_is_neither_listed_read_nor_written()
  {
    Skip.If(OperatingSystem.IsWindows(), "symbolic links need privileges on Windows");
    string[] files = (await client.GetFromJsonAsync<string[]>("/api/files"))!;
    Assert.DoesNotContain(files, f => f.Contains("linked", StringComparison.Ordinal) || f.EndsWith("Secret.cs", StringComparison.Ordinal));
    Assert.Contains(Path.Combine(Allowed, "Good.cs"), files);

    foreach (string path in new[] { Path.Combine(Allowed, "linked", "secret.txt"), Path.Combine(Allowed, "linked", "Secret.cs") })
    {
      using HttpResponseMessage read = await client.GetAsync("/api/file?path=" + Q(path));
      Assert.True(read.StatusCode == HttpStatusCode.Forbidden, $"{path}: {read.StatusCode}");
    }
    using HttpResponseMessage add = await client.PostAsJsonAsync("/api/scenes/add", new { path = Path.Combine(Allowed, "linked", "Secret.cs") });
    Assert.Equal(HttpStatusCode.Forbidden, add.StatusCode);

    // The animation writer: a frames folder through the link is refused and nothing is created outside.
    using HttpResponseMessage frames = await client.PostAsJsonAsync("/api/animation",
      new { scene = "Good", settings = new { width = 8, height = 6 }, start = 0.0, end = 0.0, fps = 1.0, folder = Path.Combine(Allowed, "linked", "frames") });
    Assert.Equal(HttpStatusCode.Forbidden, frames.StatusCode);
    Assert.False(Directory.Exists(Path.Combine(Outside, "frames")));
  }

  [SkippableFact]
  public async Task A_file_linked_to_etc_passwd_is_not_a_scene_and_its_text_never_leaves_the_studio()
  {
    Skip.If(OperatingSystem.IsWindows(), "symbolic links need privileges on Windows");
    string passwd = Path.Combine(Allowed, "Passwd.cs");
    string scenes = await client.GetStringAsync("/api/scenes");
    Assert.DoesNotContain("Passwd", scenes, StringComparison.Ordinal);
    Assert.DoesNotContain(passwd, await client.GetStringAsync("/api/files"), StringComparison.Ordinal);

    using HttpResponseMessage read = await client.GetAsync("/api/file?path=" + Q(passwd));
    Assert.Equal(HttpStatusCode.Forbidden, read.StatusCode);
    using HttpResponseMessage add = await client.PostAsJsonAsync("/api/scenes/add", new { path = passwd });
    Assert.Equal(HttpStatusCode.Forbidden, add.StatusCode);
    Assert.DoesNotContain("root:", await read.Content.ReadAsStringAsync(), StringComparison.Ordinal);
  }

  [SkippableFact]
  public async Task A_listed_script_replaced_by_a_link_leading_out_is_neither_read_written_nor_rendered()
  {
    Skip.If(OperatingSystem.IsWindows(), "symbolic links need privileges on Windows");
    string swapped = Path.Combine(Allowed, "Swapped.cs"), secret = Path.Combine(Outside, "Secret.cs");
    string before = File.ReadAllText(secret);
    File.Delete(swapped);
    File.CreateSymbolicLink(swapped, secret);

    using HttpResponseMessage read = await client.GetAsync("/api/source?scene=Swapped");
    Assert.Equal(HttpStatusCode.Forbidden, read.StatusCode);
    using HttpResponseMessage save = await client.PutAsync("/api/source?scene=Swapped", new StringContent("// overwritten\n", Encoding.UTF8));
    Assert.Equal(HttpStatusCode.Forbidden, save.StatusCode);
    Assert.Equal(before, File.ReadAllText(secret));
    using HttpResponseMessage render = await client.PostAsJsonAsync("/api/render", new { scene = "Swapped", settings = new { width = 8, height = 6 } });
    Assert.Equal(HttpStatusCode.Forbidden, render.StatusCode);
  }

  [SkippableFact]
  public async Task A_link_that_stays_inside_is_read_and_saved_through_to_its_target()
  {
    Skip.If(OperatingSystem.IsWindows(), "symbolic links need privileges on Windows");
    string alias = Path.Combine(Allowed, "Alias.cs"), good = Path.Combine(Allowed, "Good.cs");
    Assert.Contains("FiveBalls", await client.GetStringAsync("/api/file?path=" + Q(alias)));
    using HttpResponseMessage add = await client.PostAsJsonAsync("/api/scenes/add", new { path = alias });
    Assert.Equal(HttpStatusCode.OK, add.StatusCode);
    string name = (await add.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("name").GetString()!;

    using HttpResponseMessage save = await client.PutAsync("/api/source?scene=" + Q(name), new StringContent("Rendering.Scenes.Circus(scene);\n", Encoding.UTF8));
    Assert.Equal(HttpStatusCode.NoContent, save.StatusCode);
    Assert.Contains("Circus", File.ReadAllText(good));
    Assert.Equal("Good.cs", new FileInfo(alias).LinkTarget);   // still a link
  }

  [SkippableFact]
  public async Task A_save_never_writes_through_a_link_planted_beside_the_script()
  {
    Skip.If(OperatingSystem.IsWindows(), "symbolic links need privileges on Windows");
    string good = Path.Combine(Allowed, "Good.cs"), secret = Path.Combine(Outside, "secret.txt");
    // The names a save's temporary file had: a fixed one, and the new form with a guess at its random part.
    string planted = good + ".grcis-save", guessed = Path.Combine(Allowed, ".Good.cs.grcis-save-0000000000000000");
    File.CreateSymbolicLink(planted, secret);
    File.CreateSymbolicLink(guessed, secret);

    using HttpResponseMessage save = await client.PutAsync("/api/source?scene=Good", new StringContent("Rendering.Scenes.Circus(scene);\n", Encoding.UTF8));
    Assert.True(save.IsSuccessStatusCode, $"{save.StatusCode}: {await save.Content.ReadAsStringAsync()}");
    Assert.Equal("not for the studio", File.ReadAllText(secret));
    Assert.Null(new FileInfo(good).LinkTarget);                 // a file, not a link leading out
    Assert.Equal("Rendering.Scenes.Circus(scene);\n", File.ReadAllText(good));
    Assert.Equal(secret, new FileInfo(planted).LinkTarget);     // left as it was, not used
    Assert.DoesNotContain(Directory.GetFiles(Allowed, ".Good.cs.grcis-save-*"), f => f != guessed);
  }

  [SkippableFact]
  public void Real_paths_follow_every_link_on_the_way_and_refuse_a_loop()
  {
    Skip.If(OperatingSystem.IsWindows(), "symbolic links need privileges on Windows");
    Assert.Equal(Path.Combine(Outside, "secret.txt"), AllowedFiles.RealPath(Path.Combine(Allowed, "linked", "secret.txt")));
    Assert.Equal(Path.Combine(Allowed, "Good.cs"), AllowedFiles.RealPath(Path.Combine(Allowed, "Alias.cs")));
    // A missing tail (a file about to be written) is kept after the resolved folders.
    Assert.Equal(Path.Combine(Outside, "new", "out0000.png"), AllowedFiles.RealPath(Path.Combine(Allowed, "linked", "new", "out0000.png")));
    string loop = Path.Combine(root, "loop");
    File.CreateSymbolicLink(loop, loop);
    Assert.Throws<IOException>(() => AllowedFiles.RealPath(Path.Combine(loop, "x")));
    Assert.False(new AllowedFiles([root]).Allows(Path.Combine(loop, "x")));
  }
}
