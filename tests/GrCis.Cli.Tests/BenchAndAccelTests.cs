using System.Linq;
using System.Text.Json;
using Rendering;
using Rendering.Imaging;

namespace GrCis.Cli.Tests;

/// <summary><c>grcis render --accel</c> and a tiny <c>grcis bench --quick</c> (the full suite takes minutes: not in CI).</summary>
public class BenchAndAccelTests
{
  [Fact]
  public void Render_accel_none_and_bvh_write_the_same_image()
  {
    using var dir = new TempDirectory();
    CliRun slow = CliRun.Of(dir.Path, "render", "Two spheres", "--size", "48x36", "--accel", "none", "-o", "none.png", "-q");
    CliRun fast = CliRun.Of(dir.Path, "render", "Two spheres", "--size", "48x36", "--accel", "bvh", "-o", "bvh.png", "-q");
    Assert.Equal(0, slow.ExitCode);
    Assert.Equal(0, fast.ExitCode);
    Assert.Equal(PngFile.Load(dir.File("none.png")).Data, PngFile.Load(dir.File("bvh.png")).Data);
  }

  [Fact]
  public void Render_rejects_an_unknown_accel_mode()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", "--size", "8x6", "--accel", "kd", "-o", "x.png");
    Assert.Equal(ExitCodes.Usage, run.ExitCode);
    Assert.Contains("kd", run.Error);
    Assert.Empty(dir.AllFiles());
  }

  [Fact]
  public void Render_reports_rays_per_second_from_per_thread_counters()
  {
    using var dir = new TempDirectory();
    long before = System.Threading.Interlocked.Read(ref Intersection.countRays);
    CliRun run = CliRun.Of(dir.Path, "render", "Five balls", "--size", "64x48", "--threads", "2", "-o", "r.png");
    Assert.Equal(0, run.ExitCode);
    Assert.Contains("Mrays/s", run.Out);
    // The global GrCis counter got at least one ray per pixel from this render.
    Assert.True(System.Threading.Interlocked.Read(ref Intersection.countRays) - before >= 64 * 48);
  }

  [Fact]
  public void Bench_quick_json_lists_every_case_with_rays_and_speedup()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "bench", "--quick", "--json", "--threads", "2");
    Assert.Equal(0, run.ExitCode);
    using JsonDocument doc = JsonDocument.Parse(run.Out);
    JsonElement[] cases = doc.RootElement.EnumerateArray().ToArray();
    Assert.Equal(3, cases.Length);
    foreach (JsonElement c in cases)
    {
      Assert.True(c.GetProperty("rays").GetInt64() > 0, c.ToString());
      Assert.True(c.GetProperty("raysPerSecond").GetDouble() > 0, c.ToString());
      Assert.True(c.GetProperty("speedup").GetDouble() > 0, c.ToString());
      Assert.Equal(2, c.GetProperty("threads").GetInt32());
    }
    Assert.Contains("faithful", run.Error);
    // Only the mesh case reports its triangle count (the mesh-size plot's x axis).
    Assert.Equal(JsonValueKind.Null, cases[0].GetProperty("triangles").ValueKind);
    Assert.InRange(cases[2].GetProperty("triangles").GetInt64(), 1_800, 2_200);
  }

  [Fact]
  public void Bench_text_output_names_the_small_faithful_size()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "bench", "--quick", "--scene", "five-balls");
    Assert.Equal(0, run.ExitCode);
    string line = Assert.Single(run.Out.Split('\n', System.StringSplitOptions.RemoveEmptyEntries));
    Assert.Contains("none@24x18", line);
    Assert.Contains("speedup", line);
  }

  [Fact]
  public void Bench_with_an_unmatched_scene_is_a_usage_error()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "bench", "--quick", "--scene", "no-such-case");
    Assert.Equal(ExitCodes.Usage, run.ExitCode);
  }

  [Fact]
  public void Bench_scaling_times_one_thread_and_n_threads_and_the_machine_ceiling()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "bench", "--quick", "--json", "--no-slow", "--scaling", "--threads", "2", "--scene", "five-balls");
    Assert.Equal(0, run.ExitCode);
    using JsonDocument doc = JsonDocument.Parse(run.Out);
    JsonElement c = Assert.Single(doc.RootElement.EnumerateArray().ToArray());
    double one = c.GetProperty("oneThreadSeconds").GetDouble(), two = c.GetProperty("threadsSeconds").GetDouble();
    Assert.True(one > 0 && two > 0, c.ToString());
    Assert.Equal(one / two, c.GetProperty("scaling").GetDouble(), 9);
    // Two threads of pure arithmetic: at most a little over two cores' worth; the lower bound is loose because
    // the other test projects run at the same time on the same cores and may take the second thread's core.
    double ceiling = c.GetProperty("scalingCeiling").GetDouble();
    Assert.InRange(ceiling, 0.1, 2.5);
    Assert.Contains("ceiling", run.Error);
    Assert.Equal(JsonValueKind.Null, c.GetProperty("speedup").ValueKind);
  }
}
