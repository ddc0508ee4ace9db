using System;
using System.Buffers.Binary;
using System.IO;
using GrCis.Bench.Plots;

namespace GrCis.Bench.Tests;

public sealed class PlotsTests : IDisposable
{
  readonly string dir = Path.Combine(Path.GetTempPath(), "grcis-plots-" + Guid.NewGuid().ToString("N"));

  public PlotsTests() => Directory.CreateDirectory(dir);

  public void Dispose() => Directory.Delete(dir, recursive: true);

  string Write(string name, string text)
  {
    string path = Path.Combine(dir, name);
    File.WriteAllText(path, text);
    return path;
  }

  /// <summary>bench/results of this repository, found upwards from the test's folder.</summary>
  static string RecordedResults()
  {
    for (DirectoryInfo? d = new(AppContext.BaseDirectory); d != null; d = d.Parent)
      if (File.Exists(Path.Combine(d.FullName, "bench", "results", "2026-11-24-povray.tsv")))
        return Path.Combine(d.FullName, "bench", "results");
    throw new InvalidOperationException("bench/results not found above " + AppContext.BaseDirectory);
  }

  [Fact]
  public void Tsv_row_with_a_missing_cell_names_the_file_and_line()
  {
    string path = Write("t.tsv", "# date: 2026-11-26\na\tb\n1\t2\n\n3\n");
    var e = Assert.Throws<PlotInputException>(() => TsvTable.Read(path));
    Assert.Equal($"{path}:5: 1 cells, the header row has 2", e.Message);
  }

  [Fact]
  public void Tsv_header_lines_and_not_measured_cells_are_read()
  {
    string path = Write("t.tsv", "# date: 2026-11-26\n# commit: abc1234\nx\ty\n1.5\t-\n");
    TsvTable t = TsvTable.Read(path);
    Assert.Equal("abc1234", t.Header["commit"]);
    Assert.Equal(1.5, t.Rows[0].Number("x"));
    Assert.Null(t.Rows[0].NumberOrNone("y"));
    var e = Assert.Throws<PlotInputException>(() => t.Rows[0].Number("y"));
    Assert.StartsWith($"{path}:4:", e.Message);
  }

  [Fact]
  public void Tsv_cell_that_is_not_a_number_names_the_column_and_line()
  {
    string path = Write("t.tsv", "x\n0,5\n");
    var e = Assert.Throws<PlotInputException>(() => TsvTable.Read(path).Rows[0].Number("x"));
    Assert.Equal($"{path}:2: column 'x': '0,5' is not a number", e.Message);
  }

  [Fact]
  public void Bench_json_as_printed_is_one_run_and_keeps_the_triangle_count()
  {
    string path = Write("b.json", """[{"id": "mesh-1m", "name": "Torus mesh 1M", "threads": 2, "cpuSeconds": 6.1, "rays": 14872736, "triangles": 1000000, "scaling": null}]""");
    BenchJson b = BenchJson.Read(path);
    BenchPoint p = Assert.Single(Assert.Single(b.Runs).Results);
    Assert.Equal(1_000_000, p.Triangles);
    Assert.Null(p.Scaling);
  }

  [Fact]
  public void Bench_json_record_carries_its_header_and_every_run()
  {
    string path = Write("b.json", """
      {"date": "2026-11-24", "commit": "7406c32",
       "runs": [{"label": "one", "results": [{"id": "a", "name": "A", "threads": 2, "scaling": 1.9}]},
                {"label": "two", "results": [{"id": "a", "name": "A", "threads": 2, "scaling": 1.8}]}]}
      """);
    BenchJson b = BenchJson.Read(path);
    Assert.Equal("7406c32", b.Header["commit"]);
    Assert.Equal(new[] { "one", "two" }, new[] { b.Runs[0].Label, b.Runs[1].Label });
    Assert.Equal(1.8, b.Runs[1].Results[0].Scaling);
  }

  [Fact]
  public void Bench_json_syntax_error_names_the_file_and_line()
  {
    string path = Write("b.json", "[\n{\"id\": \"a\",\n\"name\": }\n]");
    var e = Assert.Throws<PlotInputException>(() => BenchJson.Read(path));
    Assert.StartsWith($"{path}:3: not JSON", e.Message);
  }

  [Fact]
  public void Bench_json_field_of_the_wrong_type_names_the_result()
  {
    string path = Write("b.json", """[{"id": "a", "name": "A", "threads": 2, "rays": "many"}]""");
    var e = Assert.Throws<PlotInputException>(() => BenchJson.Read(path));
    Assert.Contains("result 1 ('a'): field \"rays\" is not a number", e.Message);
  }

  [Fact]
  public void Plots_from_the_recorded_results_are_five_800_by_500_pngs()
  {
    string output = Path.Combine(dir, "out");
    Assert.Equal(0, PlotsCommand.Run(new[] { "--results", RecordedResults(), "--out", output }));
    foreach (string name in new[] { "cornell-rmse-vs-time.png", "thread-scaling.png", "mesh-scaling.png", "povray-ratio.png", "mesh-embree-ratio.png" })
    {
      byte[] png = File.ReadAllBytes(Path.Combine(output, name));
      Assert.Equal(new byte[] { 0x89, (byte)'P', (byte)'N', (byte)'G' }, png[..4]);
      Assert.Equal(800, BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(16)));
      Assert.Equal(500, BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(20)));
    }
    Assert.Equal(5, Directory.GetFiles(output).Length);
  }

  [Fact]
  public void Plots_with_one_malformed_input_fail_and_write_nothing()
  {
    string results = RecordedResults(), output = Path.Combine(dir, "out");
    string bad = Write("povray.tsv", "scene\tsize\tthreads\tpovray_trace_s\tours_s\nFive balls\t640×480\t2\t0.61\n");
    Assert.Equal(1, PlotsCommand.Run(new[] { "--results", results, "--out", output, "--povray", bad }));
    Assert.False(Directory.Exists(output));
  }
}
