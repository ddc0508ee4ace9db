using System.IO;
using System.Linq;
using System.Net;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text.Json;
using System.Threading.Tasks;
using GrCis.Cli;

namespace GrCis.Studio.Tests;

/// <summary>The render request's <c>algorithm</c>: <c>grcis render --algorithm</c>'s names and image, absent = the scene's choice.</summary>
public sealed class AlgorithmTests(StudioFixture studio) : IClassFixture<StudioFixture>
{
  static readonly object Settings = new { width = 48, height = 36, samplesPerPixel = 4, threads = 2 };

  /// <summary>Adds a script choosing its own distributed ray tracer to the studio; returns its scene name and path.</summary>
  async Task<(string Name, string Path)> AddScriptWithItsOwnAlgorithm()
  {
    string path = Path.Combine(studio.ScriptsFolder, "SoftBalls.cs");
    File.WriteAllText(path, "Rendering.Scenes.FiveBalls(scene);\ncontext[PropertyName.CTX_ALGORITHM] = new DistributedRayTracing();\n");
    using HttpResponseMessage added = await studio.Client.PostAsJsonAsync("/api/scenes/add", new { path });
    Assert.Equal(HttpStatusCode.OK, added.StatusCode);
    return ((await added.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("name").GetString()!, path);
  }

  /// <summary><c>grcis render</c> of <paramref name="scene"/> with <see cref="Settings"/>' values as a PNG, in-process.</summary>
  byte[] Cli(string scene, string output, params string[] more)
  {
    string png = Path.Combine(studio.Folder, output);
    var error = new StringWriter();
    string[] args = new[] { "render", scene, "--size", "48x36", "--spp", "4", "-t", "2", "-q", "-o", png }.Concat(more).ToArray();
    Assert.True(Program.Run(args, new StringWriter(), error) == 0, error.ToString());
    return File.ReadAllBytes(png);
  }

  [Fact]
  public async Task Algorithm_path_gives_the_png_of_grcis_render_algorithm_path_and_none_keeps_the_scripts_choice()
  {
    (string name, string script) = await AddScriptWithItsOwnAlgorithm();

    JsonElement path = await studio.RenderAndWait(new { scene = name, settings = Settings, algorithm = "path" });
    Assert.Equal("path", path.GetProperty("algorithm").GetString());
    Assert.Contains(path.GetProperty("notes").EnumerateArray(), n => n.GetString()!.Contains("PathTracing"));
    byte[] pathPng = await studio.Client.GetByteArrayAsync("/api/image.png");
    Assert.Equal(Cli(script, "path.png", "--algorithm", "path"), pathPng);

    // No algorithm: the script's own DistributedRayTracing, as grcis render without --algorithm.
    JsonElement own = await studio.RenderAndWait(new { scene = name, settings = Settings });
    Assert.Equal(JsonValueKind.Null, own.GetProperty("algorithm").ValueKind);
    Assert.Empty(own.GetProperty("notes").EnumerateArray());
    byte[] ownPng = await studio.Client.GetByteArrayAsync("/api/image.png");
    Assert.Equal(Cli(script, "own.png"), ownPng);
    Assert.NotEqual(pathPng, ownPng);
  }

  [Fact]
  public async Task An_unknown_algorithm_is_refused_naming_the_field_and_the_allowed_names()
  {
    using HttpResponseMessage render = await studio.Client.PostAsJsonAsync("/api/render", new { scene = "Five balls", settings = Settings, algorithm = "bogus" });
    Assert.Equal(HttpStatusCode.BadRequest, render.StatusCode);
    string message = (await render.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("detail").GetString()!;
    Assert.Contains("algorithm 'bogus'", message);
    Assert.Contains("raytracing, distributed, path", message);

    using HttpResponseMessage animation = await studio.StartAnimation(
      new { scene = "Five balls", settings = Settings, start = 0.0, end = 1.0, fps = 1.0, algorithm = "Path" });
    Assert.Equal(HttpStatusCode.BadRequest, animation.StatusCode);
    Assert.Contains("algorithm 'Path'", await animation.Content.ReadAsStringAsync());
  }

  [Fact]
  public async Task The_page_offers_the_scenes_choice_and_the_three_algorithms()
  {
    string page = await studio.Client.GetStringAsync("/");
    foreach (string option in new[] { "value=\"\">scene's choice", "value=\"raytracing\"", "value=\"distributed\"", "value=\"path\"" })
      Assert.Contains(option, page);
    Assert.Contains("algorithm: $(\"algorithm\").value", await studio.Client.GetStringAsync("/settings.js"));
  }

  [Fact]
  public async Task Progressive_render_reports_its_samples_and_noise_and_gives_the_png_of_grcis_render()
  {
    var sixteen = new { width = 48, height = 36, samplesPerPixel = 16, threads = 2 };
    JsonElement done = await studio.RenderAndWait(new { scene = "Five balls", settings = sixteen, algorithm = "path", progressive = true });
    Assert.True(done.GetProperty("progressive").GetBoolean());
    Assert.Equal(16, done.GetProperty("samples").GetInt32());
    Assert.True(done.GetProperty("noise").GetDouble() > 0.0);
    Assert.Contains("noise", done.GetProperty("statistics").GetString());
    byte[] png = await studio.Client.GetByteArrayAsync("/api/image.png");
    string cli = Path.Combine(studio.Folder, "progressive.png");
    var error = new StringWriter();
    Assert.True(Program.Run(new[] { "render", "Five balls", "--size", "48x36", "--spp", "16", "-t", "2", "--algorithm", "path", "-q", "-o", cli },
      new StringWriter(), error) == 0, error.ToString());
    Assert.Equal(File.ReadAllBytes(cli), png);
    Assert.Contains("id=\"progressive\"", await studio.Client.GetStringAsync("/"));
  }
}
