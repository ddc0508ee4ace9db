using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using ScottPlot;
using ScottPlot.TickGenerators;

namespace GrCis.Bench.Plots;

/// <summary>The bench's figures as ScottPlot plots, built from already read inputs (nothing here touches files).</summary>
public static class Figures
{
  public const int Width = 800, Height = 500;

  static readonly Color Ours = new(0x1f, 0x77, 0xb4), Other = new(0xff, 0x7f, 0x0e);

  static readonly Color[] Palette =
  {
    new(0x1f, 0x77, 0xb4), new(0xff, 0x7f, 0x0e), new(0x2c, 0xa0, 0x2c), new(0xd6, 0x27, 0x28),
    new(0x94, 0x67, 0xbd), new(0x8c, 0x56, 0x4b), new(0xe3, 0x77, 0xc2), new(0x7f, 0x7f, 0x7f),
  };

  static string Inv(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);

  /// <summary>"date, machine, commit" of an input, for the subtitle.</summary>
  static string Source(IReadOnlyDictionary<string, string> header, string fallback)
  {
    var parts = new List<string>();
    foreach (string key in new[] { "date", "commit" })
      if (header.TryGetValue(key, out string? v))
        parts.Add(key == "commit" ? "commit " + v : v);
    return parts.Count > 0 ? string.Join(", ", parts) : fallback;
  }

  static Plot NewPlot(string title, string subtitle)
  {
    var plt = new Plot();
    // A sans-serif face when the system has one (Skia falls back to its default otherwise).
    plt.Font.Set("DejaVu Sans");
    plt.Title(title + "\n" + subtitle, size: 16);
    plt.Axes.Title.Label.FontSize = 15;
    plt.Grid.MajorLineColor = Colors.Black.WithOpacity(0.15);
    plt.Grid.MinorLineColor = Colors.Black.WithOpacity(0.05);
    plt.Grid.MinorLineWidth = 1;
    return plt;
  }

  /// <summary>Decade ticks labelled with the value (the data is plotted as log10).</summary>
  static NumericAutomatic LogTicks(string format) => new()
  {
    MinorTickGenerator = new LogMinorTickGenerator(),
    IntegerTicksOnly = true,
    LabelFormatter = v => Math.Pow(10, v).ToString(format, CultureInfo.InvariantCulture),
  };

  /// <summary>(1) Cornell boxes: RMSE against render time, ours and Cycles, both variants, log-log.</summary>
  public static Plot CornellRmse(TsvTable t, string sourceNote)
  {
    t.Require("variant", "renderer", "spp", "render_s", "rmse");
    var plt = NewPlot("Cornell boxes 256×256: error against render time, ours vs Blender Cycles", sourceNote);
    string[] variants = t.Rows.Select(r => r.Text("variant")).Distinct().ToArray();
    LinePattern[] patterns = { LinePattern.Solid, LinePattern.Dashed, LinePattern.Dotted };
    MarkerShape[] shapes = { MarkerShape.FilledCircle, MarkerShape.FilledSquare, MarkerShape.FilledTriangleUp };
    int plotted = 0;
    for (int v = 0; v < variants.Length; v++)
      foreach ((string renderer, string label, Color color) in new[] { ("ours", "ours", Ours), ("cycles", "Cycles", Other) })
      {
        var rows = t.Rows.Where(r => r.Text("variant") == variants[v] && r.Text("renderer") == renderer)
          .Select(r => (row: r, s: r.NumberOrNone("render_s"), e: r.NumberOrNone("rmse"), spp: r.Number("spp")))
          .Where(p => p.s != null && p.e != null).OrderBy(p => p.s).ToArray();
        foreach (var p in rows)
          if (p.s <= 0 || p.e <= 0)
            throw p.row.Error("render_s and rmse must be positive on a log scale");
        if (rows.Length == 0)
          continue;
        var s = plt.Add.Scatter(rows.Select(p => Math.Log10(p.s!.Value)).ToArray(), rows.Select(p => Math.Log10(p.e!.Value)).ToArray(), color);
        s.LegendText = $"{label}, {variants[v]} box";
        s.LinePattern = patterns[v % patterns.Length];
        s.LineWidth = 2;
        s.MarkerShape = shapes[v % shapes.Length];
        s.MarkerSize = 8;
        plotted++;
        if (renderer == "ours")
          foreach (var p in rows)
          {
            var txt = plt.Add.Text(Inv($"{p.spp:0} spp"), Math.Log10(p.s!.Value), Math.Log10(p.e!.Value));
            txt.LabelFontSize = 11;
            txt.LabelFontColor = Colors.Black.WithOpacity(0.6);
            txt.LabelAlignment = Alignment.UpperRight;
            txt.OffsetX = -4;
            txt.OffsetY = 4;
          }
      }
    if (plotted == 0)
      throw new PlotInputException(t.File, 0, "no measured rows (renderer 'ours' or 'cycles' with render_s and rmse)");
    plt.Axes.Bottom.TickGenerator = LogTicks("0.##");
    plt.Axes.Left.TickGenerator = LogTicks("0.###");
    var all = t.Rows.Where(r => r.Text("renderer") is "ours" or "cycles" && r.NumberOrNone("render_s") != null && r.NumberOrNone("rmse") != null).ToArray();
    plt.Axes.SetLimits(Math.Log10(all.Min(r => r.Number("render_s"))) - 0.2, Math.Log10(all.Max(r => r.Number("render_s"))) + 0.08,
      Math.Log10(all.Min(r => r.Number("rmse"))) - 0.15, Math.Log10(all.Max(r => r.Number("rmse"))) + 0.1);
    plt.XLabel("render time, s (log scale)");
    plt.YLabel("RMSE of linear radiance vs reference (log)");
    plt.ShowLegend(Alignment.UpperRight);
    return plt;
  }

  /// <summary>(2) Thread scaling: speed-up of N threads over one, per scene and run, with the ideal line and the machine's ceiling.</summary>
  public static Plot ThreadScaling(BenchJson data)
  {
    var plt = NewPlot("Thread scaling: speed-up over one thread (640×480, 16 spp)", Source(data.Header, data.File));
    var scenes = new List<string>();
    int maxThreads = 1;
    foreach (BenchRun run in data.Runs)
      foreach (BenchPoint p in run.Results)
      {
        if (p.Scaling is null)
          throw new PlotInputException(data.File, 0, $"result '{p.Id}' has no \"scaling\" (run grcis bench with --scaling)");
        if (p.Threads < 1)
          throw new PlotInputException(data.File, 0, $"result '{p.Id}' has no \"threads\"");
        maxThreads = Math.Max(maxThreads, p.Threads);
        if (!scenes.Contains(p.Name))
          scenes.Add(p.Name);
      }
    if (scenes.Count == 0)
      throw new PlotInputException(data.File, 0, "no results");

    var ideal = plt.Add.Line(1, 1, maxThreads, maxThreads);
    ideal.LineColor = Colors.Black.WithOpacity(0.5);
    ideal.LinePattern = LinePattern.Dashed;
    ideal.LineWidth = 1.5f;
    ideal.LegendText = "ideal (speed-up = threads)";

    // Each scene's line ends at its mean; its runs' points sit side by side around the thread count, so they do not hide each other.
    double step = 0.2 / Math.Max(1, scenes.Count);
    for (int i = 0; i < scenes.Count; i++)
    {
      var points = data.Runs.SelectMany(r => r.Results).Where(p => p.Name == scenes[i]).ToArray();
      int n = points[0].Threads;
      double x = n - 0.1 + (i + 0.5) * step;
      double mean = points.Average(p => p.Scaling!.Value);
      var line = plt.Add.Scatter(new[] { 1.0, n }, new[] { 1.0, mean }, Palette[i % Palette.Length]);
      line.LineWidth = 1.5f;
      line.MarkerSize = 0;
      line.LegendText = Inv($"{scenes[i]} ({string.Join(", ", points.Select(p => p.Scaling!.Value.ToString("0.00", CultureInfo.InvariantCulture)))}×)");
      var dots = plt.Add.Scatter(points.Select(_ => x).ToArray(), points.Select(p => p.Scaling!.Value).ToArray(), Palette[i % Palette.Length]);
      dots.LineWidth = 0;
      dots.MarkerSize = 9;
      dots.MarkerShape = MarkerShape.FilledCircle;
    }
    var ceilings = data.Runs.SelectMany(r => r.Results).Where(p => p.ScalingCeiling != null)
      .GroupBy(p => (p.Threads, p.ScalingCeiling)).Select(g => g.First()).ToArray();
    if (ceilings.Length > 0)
    {
      var c = plt.Add.Scatter(ceilings.Select(p => (double)p.Threads - 0.15).ToArray(), ceilings.Select(p => p.ScalingCeiling!.Value).ToArray(), Colors.Black);
      c.LineWidth = 0;
      c.MarkerShape = MarkerShape.FilledDiamond;
      c.MarkerSize = 11;
      c.LegendText = Inv($"machine ceiling, pure arithmetic ({string.Join(", ", ceilings.Select(p => p.ScalingCeiling!.Value.ToString("0.00", CultureInfo.InvariantCulture)))}×)");
    }
    double[] ticks = Enumerable.Range(1, maxThreads).Select(k => (double)k).ToArray();
    plt.Axes.Bottom.SetTicks(ticks, ticks.Select(k => k.ToString(CultureInfo.InvariantCulture)).ToArray());
    plt.Axes.SetLimits(0.8, maxThreads + 0.3, 0.8, maxThreads + 0.3);
    plt.XLabel("threads");
    plt.YLabel("speed-up (one-thread time ÷ N-thread time)");
    plt.ShowLegend(Alignment.UpperLeft);
    return plt;
  }

  /// <summary>(3) Mesh-size scaling: processor time per ray against the triangle count (log x).</summary>
  public static Plot MeshScaling(BenchJson data)
  {
    var plt = NewPlot("Mesh size: processor time per ray (640×480, 16 spp, BVH)", Source(data.Header, data.File));
    var torus = new List<(double tri, double ns, string name)>();
    var files = new List<(double tri, double ns, string name)>();
    foreach (BenchRun run in data.Runs)
      foreach (BenchPoint p in run.Results)
      {
        if (p.Triangles is not double tri || tri <= 0)
          throw new PlotInputException(data.File, 0, $"result '{p.Id}' has no \"triangles\" (mesh cases of grcis bench report it)");
        if (p.CpuSeconds is not double cpu || p.Rays is not double rays || rays <= 0)
          throw new PlotInputException(data.File, 0, $"result '{p.Id}' needs \"cpuSeconds\" and \"rays\"");
        string name = p.Name.StartsWith("Mesh ", StringComparison.Ordinal) ? p.Name[5..].Replace(".obj.gz", "").Replace(".obj", "") : p.Name;
        (p.Id == "mesh-file" ? files : torus).Add((tri, cpu / rays * 1e9, name));
      }
    if (torus.Count + files.Count == 0)
      throw new PlotInputException(data.File, 0, "no results");
    double top = 0;
    foreach ((var list, string label, Color color, MarkerShape shape) in new[]
             {
               (torus, "procedural torus (same camera)", Ours, MarkerShape.FilledCircle),
               (files, "OBJ meshes, each fitted to the view", Other, MarkerShape.FilledSquare),
             })
    {
      if (list.Count == 0)
        continue;
      list.Sort((a, b) => a.tri.CompareTo(b.tri));
      var s = plt.Add.Scatter(list.Select(p => Math.Log10(p.tri)).ToArray(), list.Select(p => p.ns).ToArray(), color);
      s.LegendText = label;
      s.LineWidth = list == torus ? 2 : 0;
      s.MarkerShape = shape;
      s.MarkerSize = 10;
      for (int k = 0; k < list.Count; k++)
      {
        var p = list[k];
        top = Math.Max(top, p.ns);
        var txt = plt.Add.Text(Inv($"{p.name}: {p.ns:0} ns"), Math.Log10(p.tri), p.ns);
        txt.LabelFontSize = 12;
        // Neighbouring labels alternate above and below their points.
        bool above = list == torus || k % 2 == 0;
        txt.LabelAlignment = above ? Alignment.LowerCenter : Alignment.UpperCenter;
        txt.OffsetY = above ? -8 : 8;
      }
    }
    plt.Axes.Bottom.TickGenerator = LogTicks("#,0");
    double lo = Math.Log10(torus.Concat(files).Min(p => p.tri)) - 0.35;
    double hi = Math.Log10(torus.Concat(files).Max(p => p.tri)) + 0.35;
    plt.Axes.SetLimits(lo, hi, 0, top * 1.3);
    plt.XLabel("triangles (log scale)");
    plt.YLabel("CPU time per ray, ns (both threads)");
    plt.ShowLegend(Alignment.UpperLeft);
    return plt;
  }

  /// <summary>(4) Ours ÷ POV-Ray 3.7 render time per scene, one bar per thread count, with the 1.0 line.</summary>
  public static Plot PovRayRatio(TsvTable t)
  {
    t.Require("scene", "size", "threads", "povray_trace_s", "ours_s");
    var plt = NewPlot("Render time, ours ÷ POV-Ray 3.7 (16 vs 17 samples per pixel; below 1: ours is faster)", Source(t.Header, t.File));
    var groups = new List<string>();
    var threadCounts = new List<int>();
    var values = new List<(string group, int threads, double ratio)>();
    foreach (TsvRow r in t.Rows)
    {
      double pov = r.Number("povray_trace_s"), ours = r.Number("ours_s"), threads = r.Number("threads");
      if (pov <= 0 || ours <= 0 || threads < 1 || threads != Math.Floor(threads))
        throw r.Error("times must be positive and threads a whole number ≥ 1");
      string g = r.Text("scene") + "\n" + r.Text("size");
      if (!groups.Contains(g))
        groups.Add(g);
      if (!threadCounts.Contains((int)threads))
        threadCounts.Add((int)threads);
      values.Add((g, (int)threads, ours / pov));
    }
    if (values.Count == 0)
      throw new PlotInputException(t.File, 0, "no rows");
    threadCounts.Sort((a, b) => b.CompareTo(a));
    double width = 0.8 / threadCounts.Count;
    var bars = new List<Bar>();
    for (int k = 0; k < threadCounts.Count; k++)
    {
      Color color = Palette[k % Palette.Length];
      foreach (var v in values.Where(v => v.threads == threadCounts[k]))
      {
        double x = groups.IndexOf(v.group) - 0.4 + width * (k + 0.5);
        bars.Add(new Bar { Position = x, Value = v.ratio, FillColor = color, Size = width * 0.9, Label = v.ratio.ToString("0.00", CultureInfo.InvariantCulture) });
      }
      plt.Legend.ManualItems.Add(new LegendItem { LabelText = threadCounts[k] == 1 ? "1 thread" : $"{threadCounts[k]} threads", FillColor = color });
    }
    var barPlot = plt.Add.Bars(bars);
    barPlot.ValueLabelStyle.FontSize = 12;
    var one = plt.Add.HorizontalLine(1.0);
    one.LineColor = Colors.Black;
    one.LinePattern = LinePattern.Dashed;
    one.LineWidth = 1.5f;
    plt.Legend.ManualItems.Add(new LegendItem { LabelText = "POV-Ray = 1.0", LineColor = Colors.Black, LinePattern = LinePattern.Dashed, LineWidth = 1.5f });
    plt.Axes.Bottom.SetTicks(Enumerable.Range(0, groups.Count).Select(i => (double)i).ToArray(), groups.ToArray());
    plt.Axes.Bottom.MajorTickStyle.Length = 0;
    plt.Axes.SetLimits(-0.6, groups.Count - 0.4, 0, Math.Max(1.25, values.Max(v => v.ratio) * 1.15));
    plt.YLabel("ours ÷ POV-Ray, render time");
    plt.ShowLegend(Alignment.UpperRight);
    return plt;
  }

  /// <summary>
  /// (5) Mesh queries against Intel Embree (<c>embree --tsv</c>): per ray set, the time of the library's mesh kernel
  /// (<c>TriangleMesh</c>), of its scene query (<c>PreparedScene</c>) and of Embree's 16-ray packets over Embree's
  /// single-ray time, at the table's smallest thread count, and the build; lines at 1 (Embree) and 2 (the goal).
  /// A row that disagreed with Embree on some ray is refused: its time is not of the same work.
  /// </summary>
  public static Plot EmbreeRatio(TsvTable t)
  {
    t.Require("rays", "query", "threads", "time_ratio", "mismatches");
    var plt = NewPlot("Mesh ray queries: time ÷ Intel Embree's single-ray time (below 2: the goal)",
                      Source(t.Header, t.File) + (t.Header.TryGetValue("mesh", out string? mesh) ? "; " + mesh : ""));
    double? threads = null;
    foreach (TsvRow r in t.Rows)
      if (r.NumberOrNone("threads") is double n)
        threads = Math.Min(threads ?? n, n);
    (string prefix, string label)[] series =
    {
      ("TriangleMesh", "TriangleMesh (the mesh kernel)"), ("PreparedScene", "PreparedScene (what the renderer calls)"),
      ("Embree rtcIntersect16", "Embree, 16-ray packets"), ("mesh BVH", "build ÷ Embree MEDIUM, 1 thread"),
    };
    var groups = new List<string>();
    var values = new List<(string group, int series, double ratio)>();
    foreach (TsvRow r in t.Rows)
    {
      if (r.Number("mismatches") != 0)
        throw r.Error($"{r.Text("query")} disagreed with Embree on {r.Text("mismatches")} rays");
      bool build = r.Text("rays") == Embree.EmbreeTsv.BuildRays;
      if (!build && r.NumberOrNone("threads") != threads)
        continue;
      int k = Array.FindIndex(series, s => r.Text("query").StartsWith(s.prefix, StringComparison.Ordinal));
      if (k < 0)
        continue;   // Embree's single-ray row: the reference, 1 by definition
      double ratio = r.Number("time_ratio");
      if (ratio <= 0)
        throw r.Error("time_ratio must be positive");
      string group = build ? "build" : Wrap(r.Text("rays"), 16);
      if (!groups.Contains(group))
        groups.Add(group);
      values.Add((group, k, ratio));
    }
    if (values.Count == 0)
      throw new PlotInputException(t.File, 0, "no library rows");
    int[] used = values.Select(v => v.series).Distinct().Order().ToArray();
    var bars = new List<Bar>();
    foreach (int k in used)
    {
      Color color = Palette[k % Palette.Length];
      foreach (var v in values.Where(v => v.series == k))
      {
        // Within a group, the series it has, side by side.
        int[] inGroup = values.Where(w => w.group == v.group).Select(w => w.series).Order().ToArray();
        double w = 0.8 / Math.Max(inGroup.Length, 2);
        double x = groups.IndexOf(v.group) + w * (Array.IndexOf(inGroup, k) + 0.5 - 0.5 * inGroup.Length);
        bars.Add(new Bar { Position = x, Value = v.ratio, FillColor = color, Size = w * 0.9, Label = v.ratio.ToString("0.00", CultureInfo.InvariantCulture) });
      }
      plt.Legend.ManualItems.Add(new LegendItem { LabelText = series[k].label, FillColor = color });
    }
    var barPlot = plt.Add.Bars(bars);
    barPlot.ValueLabelStyle.FontSize = 12;
    foreach ((double y, string label, LinePattern pattern) in new[] { (1.0, "Embree = 1", LinePattern.Dashed), (2.0, "goal: 2", LinePattern.Dotted) })
    {
      var line = plt.Add.HorizontalLine(y);
      line.LineColor = Colors.Black;
      line.LinePattern = pattern;
      line.LineWidth = 1.5f;
      plt.Legend.ManualItems.Add(new LegendItem { LabelText = label, LineColor = Colors.Black, LinePattern = pattern, LineWidth = 1.5f });
    }
    plt.Axes.Bottom.SetTicks(Enumerable.Range(0, groups.Count).Select(i => (double)i).ToArray(), groups.ToArray());
    plt.Axes.Bottom.MajorTickStyle.Length = 0;
    // Head room for the legend (a third of the height) above the tallest bar.
    plt.Axes.SetLimits(-0.6, groups.Count - 0.4, 0, Math.Max(2.5, values.Max(v => v.ratio) * 1.6));
    plt.YLabel(Inv($"time ÷ Embree's single-ray time, {threads ?? 1} thread{(threads > 1 ? "s" : "")}"));
    plt.ShowLegend(Alignment.UpperLeft);
    return plt;
  }

  /// <summary>The words of <paramref name="text"/> on lines of about <paramref name="width"/> characters (tick labels).</summary>
  static string Wrap(string text, int width)
  {
    var lines = new List<string>();
    string line = "";
    foreach (string word in text.Split(' ', StringSplitOptions.RemoveEmptyEntries))
    {
      if (line.Length > 0 && line.Length + 1 + word.Length > width)
      {
        lines.Add(line);
        line = word;
      }
      else
        line = line.Length == 0 ? word : line + " " + word;
    }
    lines.Add(line);
    return string.Join('\n', lines);
  }
}
