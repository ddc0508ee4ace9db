using System;
using System.Collections.Generic;
using System.IO;
using ScottPlot;

namespace GrCis.Bench.Plots;

/// <summary>
/// <c>plots [--results DIR] [--out DIR] [--cornell TSV] [--scaling JSON] [--mesh JSON] [--povray TSV] [--embree TSV]</c>: draws the
/// bench's figures as PNG (<see cref="Figures.Width"/>×<see cref="Figures.Height"/>) from the recorded results.
/// Every input is read and every plot drawn before the first file is written, so bad input leaves nothing behind.
/// </summary>
public static class PlotsCommand
{
  /// <summary>The recorded inputs of the current figures, relative to the results folder.</summary>
  const string CornellDefault = "2026-11-26-cornell-cycles-mc.tsv",
    ScalingDefault = "2026-11-24-thread-scaling.json",
    MeshDefault = "2026-11-26-mesh-scaling.json",
    PovRayDefault = "2026-11-24-povray.tsv",
    EmbreeDefault = "2026-12-06-embree-ratio-evening.tsv";

  public static int Run(string[] args)
  {
    string? results = null, outDir = null, cornell = null, scaling = null, mesh = null, povray = null, embree = null;
    for (int i = 0; i < args.Length; i++)
    {
      string Value() => i + 1 < args.Length ? args[++i] : throw new ArgumentException($"plots: {args[i]} needs a value");
      try
      {
        switch (args[i])
        {
          case "--results": results = Value(); break;
          case "--out": outDir = Value(); break;
          case "--cornell": cornell = Value(); break;
          case "--scaling": scaling = Value(); break;
          case "--mesh": mesh = Value(); break;
          case "--povray": povray = Value(); break;
          case "--embree": embree = Value(); break;
          default:
            Console.Error.WriteLine($"plots: unknown option '{args[i]}'\nusage: plots [--results DIR] [--out DIR] [--cornell TSV] [--scaling JSON] [--mesh JSON] [--povray TSV] [--embree TSV]");
            return 2;
        }
      }
      catch (ArgumentException e)
      {
        Console.Error.WriteLine(e.Message);
        return 2;
      }
    }

    results ??= FindResults();
    if (results == null || !Directory.Exists(results))
    {
      Console.Error.WriteLine("plots: no results folder (run from the repository or give --results DIR)");
      return 2;
    }
    outDir ??= Path.Combine(results, "plots");
    cornell ??= Path.Combine(results, CornellDefault);
    scaling ??= Path.Combine(results, ScalingDefault);
    mesh ??= Path.Combine(results, MeshDefault);
    povray ??= Path.Combine(results, PovRayDefault);
    embree ??= Path.Combine(results, EmbreeDefault);

    var images = new List<(string name, byte[] png)>();
    try
    {
      TsvTable cornellTable = TsvTable.Read(cornell);
      string cornellNote = cornellTable.Header.TryGetValue("date", out string? d)
        ? d + (cornellTable.Header.TryGetValue("commit", out string? c) ? ", commit " + c : "")
        : Path.GetFileName(cornell);
      images.Add(("cornell-rmse-vs-time.png", Png(Figures.CornellRmse(cornellTable, cornellNote + "; 2 threads, median of 3 runs"))));
      images.Add(("thread-scaling.png", Png(Figures.ThreadScaling(BenchJson.Read(scaling)))));
      images.Add(("mesh-scaling.png", Png(Figures.MeshScaling(BenchJson.Read(mesh)))));
      images.Add(("povray-ratio.png", Png(Figures.PovRayRatio(TsvTable.Read(povray)))));
      images.Add(("mesh-embree-ratio.png", Png(Figures.EmbreeRatio(TsvTable.Read(embree)))));
    }
    catch (PlotInputException e)
    {
      Console.Error.WriteLine("plots: error: " + e.Message);
      return 1;
    }

    Directory.CreateDirectory(outDir);
    foreach ((string name, byte[] png) in images)
    {
      string path = Path.Combine(outDir, name), part = path + ".part";
      File.WriteAllBytes(part, png);
      File.Move(part, path, overwrite: true);
      Console.WriteLine($"{path}  ({png.Length / 1024.0:0} KiB)");
    }
    return 0;
  }

  static byte[] Png(Plot plot) => plot.GetImageBytes(Figures.Width, Figures.Height, ImageFormat.Png);

  /// <summary>bench/results of the repository holding the working folder (so it runs from the root or from bench/GrCis.Bench).</summary>
  static string? FindResults()
  {
    for (DirectoryInfo? dir = new(Directory.GetCurrentDirectory()); dir != null; dir = dir.Parent)
    {
      string candidate = Path.Combine(dir.FullName, "bench", "results");
      if (Directory.Exists(candidate))
        return candidate;
    }
    return null;
  }
}
