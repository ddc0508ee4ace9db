using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Net;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text.Json;
using System.Threading.Tasks;

namespace GrCis.Studio.Tests;

/// <summary>
/// <c>grcis studio DIR</c> as a newcomer starts it (issue 39): the folder's first script is selected, not the built-in
/// default; scripts are listed apart from the built-in scenes (by file name, "FiveBalls.cs" beside "Five balls"); the
/// page has an icon.
/// </summary>
public sealed class SceneListTests
{
  [Fact]
  public async Task The_folders_first_script_is_selected_and_scripts_are_labelled_apart()
  {
    DirectoryInfo folder = Directory.CreateTempSubdirectory("grcis-studio-list-");
    try
    {
      File.WriteAllText(Path.Combine(folder.FullName, "FiveBalls.cs"), "Rendering.Scenes.FiveBalls(scene);\n");
      File.WriteAllText(Path.Combine(folder.FullName, "Bezier.cs"), "Rendering.Scenes.FiveBalls(scene);\n");
      await using StudioServer server = await StudioServer.StartAsync(new StudioOptions { Paths = [folder.FullName] }, new List<string>());
      using HttpClient client = StudioFixture.ClientOf(server);

      JsonElement list = await client.GetFromJsonAsync<JsonElement>("/api/scenes");
      Assert.Equal("Bezier (2)", list.GetProperty("selected").GetString());
      var scenes = list.GetProperty("scenes").EnumerateArray()
        .Select(s => (Name: s.GetProperty("name").GetString(), Label: s.GetProperty("label").GetString(), Kind: s.GetProperty("kind").GetString()))
        .ToList();
      Assert.Contains(("Bezier", "Bezier", "BuiltIn"), scenes);
      Assert.Contains(("Five balls", "Five balls", "BuiltIn"), scenes);
      Assert.Contains(("Bezier (2)", "Bezier.cs", "Script"), scenes);
      Assert.Contains(("FiveBalls", "FiveBalls.cs", "Script"), scenes);
      Assert.Equal(scenes.Count, scenes.Select(s => s.Label).Distinct().Count());

      // The page groups the list by kind and shows the label.
      string settings = await client.GetStringAsync("/settings.js");
      Assert.Contains("optgroup", settings, StringComparison.Ordinal);
      Assert.Contains("s.label", settings, StringComparison.Ordinal);
    }
    finally
    {
      folder.Delete(recursive: true);
    }
  }

  [Fact]
  public async Task The_page_has_an_icon()
  {
    await using StudioServer server = await StudioServer.StartAsync(new StudioOptions { NoDefault = true }, new List<string>());
    using HttpClient client = StudioFixture.ClientOf(server);
    string page = await client.GetStringAsync("/");
    Assert.Contains("<link rel=\"icon\" href=\"favicon.svg\"", page, StringComparison.Ordinal);
    using HttpResponseMessage icon = await client.GetAsync("/favicon.svg");
    Assert.Equal(HttpStatusCode.OK, icon.StatusCode);
    Assert.Equal("image/svg+xml", icon.Content.Headers.ContentType?.MediaType);
    Assert.StartsWith("<svg", await icon.Content.ReadAsStringAsync(), StringComparison.Ordinal);
  }
}
