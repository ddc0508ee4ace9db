using System;
using System.IO;
using System.Linq;
using GrCis.Bench.Embree;
using GrCis.TestSupport;

namespace GrCis.Bench.Tests;

/// <summary>The Embree comparison on a small mesh: every library query must agree with Embree ray for ray.</summary>
public sealed class EmbreeComparisonTests
{
  /// <summary>The vase of the repository's scripts/data (a closed lathe mesh), found above the test binaries.</summary>
  static string RepositoryMesh()
  {
    for (DirectoryInfo? d = new(AppContext.BaseDirectory); d != null; d = d.Parent)
    {
      string candidate = Path.Combine(d.FullName, "scripts", "data", "vase.obj");
      if (File.Exists(candidate) && File.Exists(Path.Combine(d.FullName, "GrCis.sln")))
        return candidate;
    }
    throw new FileNotFoundException($"scripts/data/vase.obj not found above {AppContext.BaseDirectory}");
  }

  [SkippableFact]
  public void A_mesh_s_hits_agree_with_Embree_ray_for_ray_on_every_ray_set()
  {
    RequiredTool.Library("libembree3.so.3", EmbreeComparison.IsAvailable, EmbreeComparison.DebianPackage);
    string mesh = RepositoryMesh();
    var output = new StringWriter();
    EmbreeReport report = EmbreeComparison.Measure(
      new EmbreeOptions { MeshFile = mesh, Size = 48, Rays = 3000, Threads = new[] { 1, 2 }, Repeats = 1 }, output);

    Assert.True(report.Triangles > 100, output.ToString());
    Assert.True(report.LibraryBuild > 0.0 && report.EmbreeBuild1 > 0.0 && report.EmbreeBuildAll > 0.0);
    // Four ray sets; camera: Embree single and packets, the mesh kernel, the scene; the others three each; two thread counts.
    Assert.Equal(2 * (4 + 3 + 3 + 3), report.Rows.Count);
    foreach (EmbreeRow row in report.Rows)
    {
      Assert.True(row.Mismatches == 0, $"{row.Query} on {row.Rays}: {row.Mismatches} rays disagree with Embree\n{output}");
      Assert.True(row.Mrays > 0.0 && double.IsFinite(row.Mrays));
    }
    // Each set has hits and misses, so agreement means something.
    foreach (var set in report.Rows.GroupBy(r => r.Rays))
    {
      int rays = set.Key.StartsWith("camera", StringComparison.Ordinal) ? 48 * 48 : set.Key.StartsWith("shadow", StringComparison.Ordinal) ? set.First().ReferenceHits : 3000;
      if (!set.Key.StartsWith("shadow", StringComparison.Ordinal))
        Assert.InRange(set.First().ReferenceHits, rays / 20, rays - rays / 20);
      else
        Assert.True(set.First().ReferenceHits > 100, $"{set.First().ReferenceHits} shadow rays blocked");
    }
    Assert.Equal(0, report.Mismatches);
  }

  [SkippableFact]
  public void A_missing_mesh_file_is_one_line_naming_it_and_exit_1()
  {
    RequiredTool.Library("libembree3.so.3", EmbreeComparison.IsAvailable, EmbreeComparison.DebianPackage);
    string missing = Path.Combine(Path.GetTempPath(), "grcis-no-such-mesh-" + Guid.NewGuid().ToString("N") + ".obj");
    var output = new StringWriter();
    var error = new StringWriter();
    Assert.Equal(1, EmbreeComparison.Run(new[] { "--mesh", missing }, output, error));
    string message = error.ToString().Trim();
    Assert.DoesNotContain('\n', message);
    Assert.Contains(missing, message);
  }

  [Fact]
  public void Bad_options_are_named()
  {
    var e = Assert.Throws<ArgumentException>(() => EmbreeOptions.Parse(new[] { "--threads", "1,x" }));
    Assert.Equal("--threads: 'x' is not a positive whole number", e.Message);
    e = Assert.Throws<ArgumentException>(() => EmbreeOptions.Parse(new[] { "--frobnicate", "1" }));
    Assert.StartsWith("unknown option '--frobnicate'", e.Message);
    Assert.Equal(new[] { 2 }, EmbreeOptions.Parse(new[] { "--threads", "2" }).Threads);
    Assert.True(EmbreeOptions.Parse(new[] { "--order", "grouped" }).Grouped);
    Assert.False(EmbreeOptions.Parse(new[] { "--order", "interleaved" }).Grouped);
    Assert.False(EmbreeOptions.Parse(Array.Empty<string>()).Grouped);
    e = Assert.Throws<ArgumentException>(() => EmbreeOptions.Parse(new[] { "--order", "random" }));
    Assert.Equal("--order: 'random' is not interleaved or grouped", e.Message);
    Assert.True(EmbreeOptions.Parse(new[] { "--clock", "cpu", "--threads", "1" }).ThreadCpu);
    Assert.False(EmbreeOptions.Parse(new[] { "--clock", "wall" }).ThreadCpu);
    e = Assert.Throws<ArgumentException>(() => EmbreeOptions.Parse(new[] { "--clock", "cpu" }));   // default threads 1,2
    Assert.Equal("--clock cpu measures one thread: use it with --threads 1", e.Message);
    e = Assert.Throws<ArgumentException>(() => EmbreeOptions.Parse(new[] { "--clock", "tsc" }));
    Assert.Equal("--clock: 'tsc' is not wall or cpu", e.Message);
  }

  [SkippableFact]
  public void Thread_processor_time_gives_positive_rates_and_says_so()
  {
    RequiredTool.Library("libembree3.so.3", EmbreeComparison.IsAvailable, EmbreeComparison.DebianPackage);
    var output = new StringWriter();
    EmbreeReport report = EmbreeComparison.Measure(
      new EmbreeOptions { MeshFile = RepositoryMesh(), Size = 16, Rays = 400, Threads = new[] { 1 }, Repeats = 1, ThreadCpu = true }, output);
    Assert.Contains("thread CPU time", output.ToString());
    Assert.All(report.Rows, row => Assert.True(row.Mrays > 0.0 && double.IsFinite(row.Mrays) && row.Mismatches == 0, $"{row.Query} on {row.Rays}\n{output}"));
  }

  [SkippableFact]
  public void Grouped_rounds_time_every_query_as_often_as_interleaved_ones()
  {
    RequiredTool.Library("libembree3.so.3", EmbreeComparison.IsAvailable, EmbreeComparison.DebianPackage);
    var output = new StringWriter();
    EmbreeReport report = EmbreeComparison.Measure(
      new EmbreeOptions { MeshFile = RepositoryMesh(), Size = 16, Rays = 400, Threads = new[] { 1 }, Repeats = 2, Grouped = true }, output);
    Assert.Equal(4 + 3 + 3 + 3, report.Rows.Count);
    Assert.All(report.Rows, row => Assert.True(row.Mrays > 0.0 && double.IsFinite(row.Mrays) && row.Mismatches == 0, $"{row.Query} on {row.Rays}\n{output}"));
  }

  [SkippableFact]
  public void The_tsv_option_writes_every_measured_row_and_the_build()
  {
    RequiredTool.Library("libembree3.so.3", EmbreeComparison.IsAvailable, EmbreeComparison.DebianPackage);
    string dir = Path.Combine(Path.GetTempPath(), "grcis-embree-" + Guid.NewGuid().ToString("N"));
    Directory.CreateDirectory(dir);
    try
    {
      string tsv = Path.Combine(dir, "e.tsv");
      var output = new StringWriter();
      Assert.Equal(0, EmbreeComparison.Run(new[] { "--mesh", RepositoryMesh(), "--size", "16", "--rays", "400", "--threads", "1", "--repeats", "1", "--tsv", tsv }, output, new StringWriter()));
      Plots.TsvTable t = Plots.TsvTable.Read(tsv);
      Assert.Equal(4 + 3 + 3 + 3 + 1, t.Rows.Count);
      Assert.Equal("embree --mesh <mesh folder>/vase.obj --size 16 --rays 400 --threads 1 --repeats 1 --tsv e.tsv", t.Header["command"]);
      Assert.All(t.Rows, r => Assert.Equal(0, r.Number("mismatches")));
      Assert.Equal(new[] { tsv }, Directory.GetFiles(dir));
    }
    finally
    {
      Directory.Delete(dir, recursive: true);
    }
  }
}
