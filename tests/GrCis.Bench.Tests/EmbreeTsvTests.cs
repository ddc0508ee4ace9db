using System;
using System.IO;
using System.Linq;
using GrCis.Bench.Embree;
using GrCis.Bench.Plots;
using ScottPlot.Plottables;

namespace GrCis.Bench.Tests;

/// <summary><c>embree --tsv</c>'s table and the figure <c>plots</c> draws from it.</summary>
public sealed class EmbreeTsvTests : IDisposable
{
  readonly string dir = Path.Combine(Path.GetTempPath(), "grcis-embree-tsv-" + Guid.NewGuid().ToString("N"));

  public EmbreeTsvTests() => Directory.CreateDirectory(dir);

  public void Dispose() => Directory.Delete(dir, recursive: true);

  /// <summary>Two ray sets at one and two threads, as the comparison reports them (Embree's row first in each).</summary>
  static EmbreeReport Report(int mismatches = 0)
  {
    var report = new EmbreeReport { Triangles = 1000, LibraryBuild = 0.030, EmbreeBuild1 = 0.020, EmbreeBuildAll = 0.012 };
    foreach (int threads in new[] { 1, 2 })
    {
      report.Rows.Add(new EmbreeRow("camera, tight (25 degrees)", "Embree rtcIntersect1", threads, 8.0 * threads, 100, 0));
      report.Rows.Add(new EmbreeRow("camera, tight (25 degrees)", "Embree rtcIntersect16", threads, 16.0 * threads, 100, 0));
      report.Rows.Add(new EmbreeRow("camera, tight (25 degrees)", "TriangleMesh.IntersectFirst", threads, 4.0 * threads, 100, 0));
      report.Rows.Add(new EmbreeRow("camera, tight (25 degrees)", "PreparedScene.FirstHit", threads, 2.0 * threads, 100, mismatches));
      report.Rows.Add(new EmbreeRow("shadow rays from surface points to a light", "Embree rtcOccluded1", threads, 3.0, 50, 0));
      report.Rows.Add(new EmbreeRow("shadow rays from surface points to a light", "TriangleMesh.IntersectFirst, t <= end", threads, 1.0, 50, 0));
      report.Rows.Add(new EmbreeRow("shadow rays from surface points to a light", "PreparedScene.AnyHit", threads, 1.5, 50, 0));
    }
    return report;
  }

  string Written(EmbreeReport report)
  {
    string file = Path.Combine(dir, "embree.tsv");
    EmbreeTsv.Write(report, "test.obj", "embree --mesh <mesh folder>/test.obj", file);
    return file;
  }

  [Fact]
  public void The_table_has_a_row_per_query_and_thread_count_with_its_ratio_to_Embree_and_one_for_the_build()
  {
    TsvTable t = TsvTable.Read(Written(Report()));
    Assert.Equal(EmbreeTsv.Columns, t.Columns);
    Assert.Equal("test.obj, 1000 triangles", t.Header["mesh"]);
    Assert.Equal(14 + 1, t.Rows.Count);
    TsvRow scene2 = t.Rows.Single(r => r.Text("query") == "PreparedScene.FirstHit" && r.Number("threads") == 2);
    Assert.Equal(4.0, scene2.Number("mrays"));
    Assert.Equal(16.0, scene2.Number("embree_mrays"));
    Assert.Equal(4.0, scene2.Number("time_ratio"));
    Assert.All(t.Rows.Where(r => r.Text("query").StartsWith("Embree rtcIntersect1", StringComparison.Ordinal) && r.Text("query").Length == 20),
               r => Assert.Equal(1.0, r.Number("time_ratio")));
    TsvRow build = t.Rows[^1];
    Assert.Equal(EmbreeTsv.BuildRays, build.Text("rays"));
    Assert.Null(build.NumberOrNone("threads"));
    Assert.Equal(1.5, build.Number("time_ratio"));
    Assert.False(File.Exists(Path.Combine(dir, "embree.tsv.part")));
  }

  [Fact]
  public void The_figure_draws_the_library_rows_and_packets_of_the_fewest_threads_and_the_build()
  {
    ScottPlot.Plot plot = Figures.EmbreeRatio(TsvTable.Read(Written(Report())));
    BarPlot bars = Assert.Single(plot.GetPlottables().OfType<BarPlot>());
    // One thread: camera (packets, mesh, scene), shadow (mesh, scene), and the build; Embree's own rows are the line at 1.
    Assert.Equal(new[] { 0.5, 2.0, 3.0, 4.0, 2.0, 1.5 }.Order(), bars.Bars.Select(b => Math.Round(b.Value, 4)).Order());
    // The groups' bars do not overlap and stay within their group's slot.
    foreach (var group in bars.Bars.GroupBy(b => Math.Round(b.Position)))
    {
      var sorted = group.OrderBy(b => b.Position).ToArray();
      for (int i = 1; i < sorted.Length; i++)
        Assert.True(sorted[i].Position - sorted[i - 1].Position >= 0.5 * (sorted[i].Size + sorted[i - 1].Size) - 1e-9);
      Assert.All(sorted, b => Assert.InRange(b.Position, group.Key - 0.45, group.Key + 0.45));
    }
  }

  [Fact]
  public void A_row_that_disagreed_with_Embree_is_refused_naming_the_file_and_line()
  {
    string file = Written(Report(mismatches: 3));
    var e = Assert.Throws<PlotInputException>(() => Figures.EmbreeRatio(TsvTable.Read(file)));
    // Header lines (6, or 7 with the commit), the column row, then the camera rows: PreparedScene.FirstHit is the fourth.
    int line = Array.IndexOf(File.ReadAllLines(file), File.ReadAllLines(file).First(l => l.Contains("PreparedScene.FirstHit"))) + 1;
    Assert.Equal($"{file}:{line}: PreparedScene.FirstHit disagreed with Embree on 3 rays", e.Message);
  }
}
