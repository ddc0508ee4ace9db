using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text;
using System.Text.Json;
using System.Threading.Tasks;
using GrCis.Studio;

namespace GrCis.Bench;

/// <summary>
/// <c>GrCis.Bench studio SCRIPTS_DIR [--cycles N]</c>: the studio's three figures, in one run on a warm server.
/// (1) save-to-first-preview latency of an edited FiveBalls.cs at 640×480; (2) render time of Five balls and
/// Two spheres at 640×480, 16 spp (and Five balls path-traced, in the studio's sample passes), through the studio vs
/// <c>grcis render</c> in-process, alternating, best of 3;
/// (3) managed heap and working set over N script edit-render cycles (default 200).
/// </summary>
internal static class StudioMeasure
{
  public static int Run(string[] args)
  {
    if (args.Length < 1 || !File.Exists(Path.Combine(args[0], "FiveBalls.cs")))
    {
      Console.Error.WriteLine("usage: GrCis.Bench studio SCRIPTS_DIR [--cycles N]   (the folder with FiveBalls.cs)");
      return 2;
    }
    int cycles = args.Length >= 3 && args[1] == "--cycles" ? int.Parse(args[2], CultureInfo.InvariantCulture) : 200;
    string work = Directory.CreateTempSubdirectory("grcis-studio-bench-").FullName;
    try
    {
      File.Copy(Path.Combine(args[0], "FiveBalls.cs"), Path.Combine(work, "FiveBalls.cs"));
      return Measure(work, cycles).GetAwaiter().GetResult();
    }
    finally
    {
      Directory.Delete(work, recursive: true);
    }
  }

  static async Task<int> Measure(string work, int cycles)
  {
    await using StudioServer server = await StudioServer.StartAsync(new StudioOptions { Paths = [work] }, new List<string>());
    using var client = new HttpClient { BaseAddress = new Uri(new Uri(server.Url).GetLeftPart(UriPartial.Authority)) };
    client.DefaultRequestHeaders.Add(AccessGuard.HeaderName, server.Token);
    string script = Path.Combine(work, "FiveBalls.cs");
    string original = File.ReadAllText(script);

    Console.WriteLine($"date: {DateTime.UtcNow:yyyy-MM-dd}, {Environment.ProcessorCount} processors, .NET {Environment.Version}");

    // (1) Save-to-first-preview latency, warm.
    var full = new { width = 640, height = 480, samplesPerPixel = 1 };
    await RenderAndWait(client, "FiveBalls", full);
    var latencies = new List<double>();
    for (int i = 0; i < 11; i++)
    {
      int before = (await Status(client)).GetProperty("version").GetInt32();
      var clock = Stopwatch.StartNew();
      using (var body = new StringContent(original + $"\n// edit {i}\n", Encoding.UTF8, "text/plain"))
        (await client.PutAsync("/api/source?scene=FiveBalls", body)).EnsureSuccessStatusCode();
      while ((await Status(client)).GetProperty("version").GetInt32() == before)
        await Task.Delay(5);
      clock.Stop();
      if (i > 0)
        latencies.Add(clock.Elapsed.TotalSeconds);
      await WaitIdle(client);
    }
    latencies.Sort();
    Console.WriteLine(FormattableString.Invariant(
      $"save-to-first-preview (FiveBalls.cs, 640x480, 10 saves): median {latencies[latencies.Count / 2]:0.000} s, min {latencies[0]:0.000} s, max {latencies[^1]:0.000} s"));

    // (2) Studio vs grcis render, same scene and settings, alternating, best of 3. Ray tracing goes by tiles after
    // the coarse preview; path tracing in passes of samples (the studio's automatic choice for it).
    foreach ((string scene, string? algorithm) in new[] { ("Five balls", (string?)null), ("Two spheres", null), ("Five balls", "path") })
    {
      double bestStudio = double.MaxValue, bestCli = double.MaxValue;
      string png = Path.Combine(work, "cli.png");
      for (int round = 0; round < 3; round++)
      {
        var clock = Stopwatch.StartNew();
        await RenderAndWait(client, scene, new { width = 640, height = 480, samplesPerPixel = 16 }, algorithm);
        bestStudio = Math.Min(bestStudio, clock.Elapsed.TotalSeconds);
        clock.Restart();
        string[] args = ["render", scene, "--size", "640x480", "--spp", "16", "-q", "-o", png];
        int code = GrCis.Cli.Program.Run(algorithm == null ? args : [.. args, "--algorithm", algorithm], TextWriter.Null, TextWriter.Null);
        bestCli = Math.Min(bestCli, clock.Elapsed.TotalSeconds);
        if (code != 0)
          throw new InvalidOperationException($"grcis render {scene} failed ({code})");
      }
      Console.WriteLine(FormattableString.Invariant(
        $"{scene}{(algorithm == null ? "" : $" ({algorithm}, sample passes)")} 640x480 16 spp, best of 3: studio {bestStudio:0.000} s (request to final image), grcis render {bestCli:0.000} s (whole command, PNG saved), studio/cli {bestStudio / bestCli:0.000}"));
    }

    // (3) Memory over edit-render cycles (small image: the cycles are about scripts, not pixels).
    var small = new { width = 160, height = 120, samplesPerPixel = 1 };
    await RenderAndWait(client, "FiveBalls", small);
    for (int i = 0; i <= cycles; i++)
    {
      if (i % 50 == 0)
      {
        GC.Collect();
        GC.WaitForPendingFinalizers();
        GC.Collect();
        Console.WriteLine(FormattableString.Invariant(
          $"after {i,3} edit-render cycles: managed heap {GC.GetTotalMemory(false) / 1048576.0:0.0} MiB, working set {Process.GetCurrentProcess().WorkingSet64 / 1048576.0:0.0} MiB"));
      }
      if (i == cycles)
        break;
      int before = (await Status(client)).GetProperty("version").GetInt32();
      using (var body = new StringContent(original + $"\n// cycle {i}\n", Encoding.UTF8, "text/plain"))
        (await client.PutAsync("/api/source?scene=FiveBalls", body)).EnsureSuccessStatusCode();
      while ((await Status(client)).GetProperty("version").GetInt32() == before)
        await Task.Delay(5);
      await WaitIdle(client);
    }
    return 0;
  }

  static async Task<JsonElement> Status(HttpClient client) => await client.GetFromJsonAsync<JsonElement>("/api/status");

  static async Task RenderAndWait(HttpClient client, string scene, object settings, string? algorithm = null)
  {
    (await client.PostAsJsonAsync("/api/render", new { scene, settings, algorithm })).EnsureSuccessStatusCode();
    await WaitIdle(client, poll: 20);
  }

  // The page polls every 200 ms; 20 ms keeps the timing close without the polling itself taking a core.
  static async Task WaitIdle(HttpClient client, int poll = 5)
  {
    while (true)
    {
      JsonElement s = await Status(client);
      if (!s.GetProperty("rendering").GetBoolean() && s.GetProperty("statistics").GetString() is { Length: > 0 })
        return;
      if (s.GetProperty("error").GetString() is { Length: > 0 } error)
        throw new InvalidOperationException(error);
      await Task.Delay(poll);
    }
  }
}
