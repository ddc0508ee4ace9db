using System;
using System.Collections.Generic;
using System.IO;
using System.Net.Http;
using System.Threading.Tasks;

namespace GrCis.Studio.Tests;

/// <summary>A studio on a free loopback port over a folder with one script, and a client that knows the token.</summary>
public sealed class StudioFixture : IAsyncLifetime
{
  public string Folder { get; } = Directory.CreateTempSubdirectory("grcis-studio-").FullName;

  public StudioServer Server { get; private set; } = null!;

  public HttpClient Client { get; private set; } = null!;

  /// <summary>A client without the token.</summary>
  public HttpClient Stranger { get; private set; } = null!;

  public string ScriptsFolder => Path.Combine(Folder, "scripts");

  public async Task InitializeAsync()
  {
    Directory.CreateDirectory(ScriptsFolder);
    File.WriteAllText(Path.Combine(ScriptsFolder, "Balls.cs"), "Rendering.Scenes.FiveBalls(scene);\n");
    File.WriteAllText(Path.Combine(Folder, "secret.txt"), "not for the studio");
    Directory.CreateDirectory(Path.Combine(ScriptsFolder, "more"));
    File.WriteAllText(Path.Combine(ScriptsFolder, "more", "Flags.cs"), "Rendering.Scenes.Flags(scene);\n");
    File.WriteAllText(Path.Combine(Folder, "Outside.cs"), "Rendering.Scenes.Flags(scene);\n");
    Server = await StudioServer.StartAsync(new StudioOptions { Paths = [ScriptsFolder] }, new List<string>());
    var root = new Uri(Server.Url).GetLeftPart(UriPartial.Authority);
    Client = new HttpClient { BaseAddress = new Uri(root) };
    Client.DefaultRequestHeaders.Add(AccessGuard.HeaderName, Server.Token);
    Stranger = new HttpClient { BaseAddress = new Uri(root) };
  }

  public async Task DisposeAsync()
  {
    Client.Dispose();
    Stranger.Dispose();
    await Server.DisposeAsync();
    Directory.Delete(Folder, recursive: true);
  }
}
