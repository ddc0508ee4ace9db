using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Threading.Tasks;
using OpenQA.Selenium.Chrome;

namespace GrCis.Studio.Tests;

/// <summary>
/// A studio over a copy of the repository's scripts/ (the scripts a student opens first) plus one script that fails
/// while it runs, and one headless browser for the whole test class, made on first use (so a machine without chromium
/// skips the tests rather than failing the fixture).
/// </summary>
public sealed class ScriptsStudioFixture : IAsyncLifetime
{
  public string Folder { get; } = Directory.CreateTempSubdirectory("grcis-studio-scripts-").FullName;

  public StudioServer Server { get; private set; } = null!;

  /// <summary>The repository's scripts, as file names (the copies in <see cref="Folder"/> have the same names).</summary>
  public IReadOnlyList<string> Scripts { get; private set; } = [];

  /// <summary>The script that throws at its line 3 while it builds the scene.</summary>
  public const string Failing = "FailsAtRun";

  ChromeDriver? browser;

  public async Task InitializeAsync()
  {
    string source = RepositoryScripts();
    foreach (string file in Directory.GetFiles(source, "*", SearchOption.AllDirectories))
    {
      string copy = Path.Combine(Folder, Path.GetRelativePath(source, file));
      Directory.CreateDirectory(Path.GetDirectoryName(copy)!);
      File.Copy(file, copy);
    }
    Scripts = Directory.GetFiles(source, "*.cs").Select(Path.GetFileName).Order(StringComparer.Ordinal).ToList()!;
    File.WriteAllText(Path.Combine(Folder, Failing + ".cs"),
                      "Rendering.Scenes.FiveBalls(scene);\nobject nothing = null;\nstring text = nothing.ToString();\n");
    Server = await StudioServer.StartAsync(new StudioOptions { Paths = [Folder] }, new List<string>());
  }

  /// <summary>The class's browser, its page <paramref name="width"/> by <paramref name="height"/> CSS pixels.</summary>
  public ChromeDriver Browser(int width, int height)
  {
    if (browser == null)
      browser = BrowserTests.Browser(width, height);
    else
      BrowserTests.Resize(browser, width, height);
    return browser;
  }

  /// <summary>The script of the repository with the most lines.</summary>
  public string Longest => Scripts.MaxBy(s => File.ReadAllLines(Path.Combine(Folder, s)).Length)!;

  static string RepositoryScripts()
  {
    for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir != null; dir = dir.Parent)
      if (File.Exists(Path.Combine(dir.FullName, "GrCis.sln")))
        return Path.Combine(dir.FullName, "scripts");
    throw new InvalidOperationException("no GrCis.sln above " + AppContext.BaseDirectory);
  }

  public async Task DisposeAsync()
  {
    browser?.Quit();
    browser?.Dispose();
    await Server.DisposeAsync();
    Directory.Delete(Folder, recursive: true);
  }
}
