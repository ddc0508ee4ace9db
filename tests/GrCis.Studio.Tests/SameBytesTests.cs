using System;
using System.Buffers.Binary;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;
using System.Threading.Tasks;
using GrCis.Cli;
using GrCis.Cli.Animation;
using GrCis.Hosting;
using GrCis.Interactive;
using GrCis.Scripting;
using Rendering.Imaging;

namespace GrCis.Studio.Tests;

/// <summary>One script host for the whole class: the demo and the studio compile each script once.</summary>
public sealed class SharedScriptHost : IDisposable
{
  public ScriptHost Host { get; } = new();

  public void Dispose() => Host.Dispose();
}

/// <summary>
/// Every front end renders what <c>grcis render</c> renders: every script in scripts/ through the CLI, the demo's
/// controller and the studio's session gives the same PNG bytes; the animated ones also at set times (a still at a
/// time, as <c>--time</c>) and as animation frames (as <c>grcis animate</c>). Small and quick: 64x48, one sample.
/// </summary>
public sealed class SameBytesTests(SharedScriptHost shared) : IClassFixture<SharedScriptHost>
{
  const int Width = 64, Height = 48;

  /// <summary>What the user set in the demo's fields, marked as given as the CLI marks <c>--size</c> and <c>--spp</c>.</summary>
  static readonly RenderSettings Settings = new() { Width = Width, Height = Height, SamplesPerPixel = 1, Threads = 2 };
  const GivenSettings Given = GivenSettings.Size | GivenSettings.SamplesPerPixel;

  static readonly string[] CliSettings = ["--size", $"{Width}x{Height}", "--spp", "1", "-t", "2", "-q"];

  /// <summary>Times at which the animated scripts are rendered as stills.</summary>
  static readonly double[] Times = [0.0, 1.3, 3.75];

  static string ScriptsFolder
  {
    get
    {
      for (DirectoryInfo? d = new(AppContext.BaseDirectory); d != null; d = d.Parent)
        if (File.Exists(Path.Combine(d.FullName, "GrCis.sln")) && Directory.Exists(Path.Combine(d.FullName, "scripts")))
          return Path.Combine(d.FullName, "scripts");
      throw new InvalidOperationException($"scripts/ not found above {AppContext.BaseDirectory}");
    }
  }

  public static IEnumerable<object[]> Scripts() =>
    Directory.GetFiles(ScriptsFolder, "*.cs").Select(Path.GetFileName).Order(StringComparer.Ordinal).Select(f => new object[] { f! });

  static bool IsAnimated(string script) => File.ReadAllText(script).Contains("CTX_START_ANIM", StringComparison.Ordinal);

  static byte[] Cli(string dir, params string[] args)
  {
    var error = new StringWriter();
    int code = Program.Run(args.Concat(CliSettings).ToArray(), new StringWriter(), error);
    Assert.True(code == 0, $"grcis {string.Join(' ', args)}: {error}");
    return args[0] == "render" ? File.ReadAllBytes(args[^1]) : [];
  }

  static async Task<byte[]> Demo(DemoController demo, string dir, string name)
  {
    RenderResult? result = await demo.RenderAsync();
    Assert.NotNull(result);
    Assert.True(result.Succeeded, result.Error?.Message);
    string png = Path.Combine(dir, name);
    Assert.True(demo.SaveImage(png));
    return File.ReadAllBytes(png);
  }

  static async Task<byte[]> Studio(StudioSession studio, SceneEntry entry, RenderSettings settings)
  {
    var done = new TaskCompletionSource<RenderResult>(TaskCreationOptions.RunContinuationsAsynchronously);
    void Completed(object? sender, RenderCompletedEventArgs e) => done.TrySetResult(e.Result);
    studio.Controller.RenderCompleted += Completed;
    try
    {
      studio.Render(entry, "", settings, given: Given);
      RenderResult result = await done.Task.WaitAsync(TimeSpan.FromMinutes(2));
      Assert.True(result.Succeeded, result.Error?.Message);
    }
    finally
    {
      studio.Controller.RenderCompleted -= Completed;
    }
    // What the page gets from /api/image.png.
    (Rgb8Image image, _) = studio.DisplayImage() ?? throw new InvalidOperationException("the studio shows no image");
    return PngEncoder.Default.Encode(image);
  }

  /// <summary>
  /// A frame of <c>grcis animate</c> without its resume fingerprint (one iTXt chunk naming the render, which only the
  /// command line writes, for <c>--resume</c>); every other byte must equal the other front ends' frames.
  /// </summary>
  static byte[] WithoutFingerprint(byte[] png)
  {
    var kept = new List<byte>(png[..8]);
    byte[] keyword = Encoding.Latin1.GetBytes(FrameFingerprint.Keyword + "\0");
    int found = 0;
    for (int at = 8; at < png.Length;)
    {
      int length = BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(at, 4));
      int end = at + 12 + length;
      if (Encoding.ASCII.GetString(png, at + 4, 4) == "iTXt" && png.AsSpan(at + 8, length).StartsWith(keyword))
        found++;
      else
        kept.AddRange(png[at..end]);
      at = end;
    }
    Assert.Equal(1, found);
    return kept.ToArray();
  }

  [Theory]
  [MemberData(nameof(Scripts))]
  public async Task Script_renders_the_same_bytes_through_the_cli_the_demo_and_the_studio(string file)
  {
    string script = Path.Combine(ScriptsFolder, file);
    string dir = Directory.CreateTempSubdirectory("grcis-same-").FullName;
    try
    {
      var catalog = new SceneCatalog(shared.Host);
      SceneEntry entry = catalog.AddScriptFile(script);
      using var demo = new DemoController(catalog) { Settings = Settings, Given = Given, Selected = entry };
      using var studio = new StudioSession(new DemoController(catalog));

      byte[] cli = Cli(dir, "render", script, "-o", Path.Combine(dir, "cli.png"));
      Assert.Equal(cli, await Demo(demo, dir, "demo.png"));
      Assert.Equal(cli, await Studio(studio, entry, Settings));

      if (!IsAnimated(script))
        return;

      // Stills at set times: --time on the command line, the time field of the window and the page.
      foreach (double t in Times)
      {
        string time = t.ToString(System.Globalization.CultureInfo.InvariantCulture);
        byte[] at = Cli(dir, "render", script, "--time", time, "-o", Path.Combine(dir, $"cli-{time}.png"));
        demo.Settings = Settings with { Time = t };
        Assert.Equal(at, await Demo(demo, dir, $"demo-{time}.png"));
        Assert.Equal(at, await Studio(studio, entry, Settings with { Time = t }));
        if (t > 0.0)
          Assert.NotEqual(cli, at);   // the scene moves (its start is the default time)
      }

      // Frames of an animation: grcis animate, the window's animation run and the page's.
      Cli(dir, "animate", script, "-o", Path.Combine(dir, "cli", "out####.png"), "--from", "0.5", "--to", "1.25", "--fps", "4");
      demo.Settings = Settings;
      AnimationRun run = demo.CreateAnimation(0.5, 1.25, 4.0);
      Assert.Equal(4, await run.RunAsync(Path.Combine(dir, "demo", "out####.png")));
      studio.Controller.Selected = entry;
      studio.Controller.Settings = Settings;
      studio.Controller.Given = Given;
      StudioAnimation page = StudioAnimation.Start(studio.Controller.CreateAnimation(0.5, 1.25, 4.0), null);
      for (int k = 0; k < 4; k++)
      {
        byte[] frame = WithoutFingerprint(File.ReadAllBytes(Path.Combine(dir, "cli", $"out{k:D4}.png")));
        Assert.Equal(frame, File.ReadAllBytes(Path.Combine(dir, "demo", $"out{k:D4}.png")));
        Assert.Equal(frame, await Frame(page, k));
      }
    }
    finally
    {
      Directory.Delete(dir, recursive: true);
    }
  }

  static async Task<byte[]> Frame(StudioAnimation animation, int k)
  {
    DateTime deadline = DateTime.UtcNow + TimeSpan.FromMinutes(2);
    while (true)
    {
      if (animation.Frame(k) is byte[] png)
        return png;
      Assert.True(DateTime.UtcNow < deadline, $"frame {k} was not rendered");
      await Task.Delay(20);
    }
  }
}
