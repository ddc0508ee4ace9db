using Scene3D;
using System;
using System.Collections.Generic;
using System.IO;
using System.IO.Compression;
using System.Linq;
using GrCis.Cli.Jobs;
using GrCis.Hosting;

namespace GrCis.Cli.Tests;

/// <summary>
/// Inputs that once hung, crashed or misled: each ends with one line <c>grcis: error: …</c>, its exit
/// code and no file, in bounded time and memory.
/// </summary>
public class HostileInputTests
{
  static void AssertRejected(CliRun run, TempDirectory dir, int exitCode, params string[] fragments)
  {
    Assert.Equal(exitCode, run.ExitCode);
    string line = Assert.Single(run.ErrorLines);
    Assert.StartsWith("grcis: error: ", line);
    foreach (string f in fragments)
      Assert.Contains(f, line, StringComparison.Ordinal);
    Assert.DoesNotContain(dir.AllFiles(), f => f.EndsWith(".png", StringComparison.Ordinal) || f.Contains(".tmp-", StringComparison.Ordinal));
  }

  [Theory]
  [InlineData("")]
  [InlineData("   \n\t\n")]
  [InlineData("// a scene, one day\n/* nothing yet */\n")]
  public void Empty_script_says_it_is_empty(string text)
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("empty.cs"), text);
    AssertRejected(CliRun.Of(dir.Path, "render", "empty.cs", "-o", "x.png", "-q"), dir, ExitCodes.Failure, "'" + dir.File("empty.cs") + "' is empty");
  }

  [Fact]
  public void Spp_above_the_limit_is_a_usage_error_before_any_work()
  {
    using var dir = new TempDirectory();
    AssertRejected(CliRun.Of(dir.Path, "render", "--size", "8x8", "--spp", "1000000000", "-o", "x.png"), dir, ExitCodes.Usage,
      "invalid --spp 1000000000", $"at most {RenderSettings.MaxSamplesPerPixel}");
    Assert.Equal(0, CliRun.Of(dir.Path, "render", "--size", "2x2", "--spp", RenderSettings.MaxSamplesPerPixel.ToString(System.Globalization.CultureInfo.InvariantCulture), "-o", "x.png", "-q").ExitCode);
  }

  [Fact]
  public void Script_asking_for_too_many_samples_fails_naming_the_limit()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("greedy.cs"), ScriptCommandTests.SceneBody + "\ncontext[PropertyName.CTX_SUPERSAMPLING] = 100000000;\n");
    AssertRejected(CliRun.Of(dir.Path, "render", "greedy.cs", "--size", "8x8", "-o", "x.png", "-q"), dir, ExitCodes.Failure,
      "supersampling 100000000", RenderSettings.MaxSamplesPerPixel.ToString(System.Globalization.CultureInfo.InvariantCulture));
  }

  [Fact]
  public void Memory_budget_grows_with_the_pixels_and_names_both_figures()
  {
    Assert.Equal(MemoryBudget.Baseline + 640L * 480 * MemoryBudget.BytesPerPixel, MemoryBudget.Needed(new ImageSize(640, 480)));
    MemoryBudget.Check(new ImageSize(1000, 1000), available: MemoryBudget.Needed(new ImageSize(1000, 1000)));
    var e = Assert.Throws<CliFailure>(() => MemoryBudget.Check(new ImageSize(16384, 16384), available: 1L << 30));
    Assert.Equal("a 16384x16384 image needs about 4.1 GiB of memory, but this process can use 1.0 GiB; render a smaller --size", e.Message);
  }

  /// <summary>512 MiB of managed heap for the process (what a small container or a batch job's limit gives).</summary>
  static readonly Dictionary<string, string> SmallHeap = new() { ["DOTNET_GCHeapHardLimit"] = "0x20000000" };

  const string Background = """
    scene.Camera = new StaticCamera(new Vector3d(0, 0, -5), new Vector3d(0, 0, 1), 60.0);
    scene.Sources = new LinkedList<ILightSource>();
    scene.BackgroundColor = new double[] { 0.1, 0.2, 0.3 };
    scene.Intersectable = new CSGInnerNode(SetOperation.Union);
    """;

  [Fact]
  public void Size_beyond_the_memory_limit_is_refused_before_rendering()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("bg.cs"), Background);
    var (code, stdout, error) = GrcisProcess.Run(dir.Path, SmallHeap, "render", "bg.cs", "--size", "16000x16000", "-o", "big.png", "-q");
    Assert.Equal(ExitCodes.Failure, code);
    Assert.Equal("", stdout);
    string line = Assert.Single(error.Split('\n', StringSplitOptions.RemoveEmptyEntries));
    Assert.StartsWith("grcis: error: a 16000x16000 image needs about 3.9 GiB of memory, but this process can use 512 MiB", line);
    Assert.Empty(dir.AllFiles().Where(f => !f.EndsWith("bg.cs", StringComparison.Ordinal)));
  }

  [Fact]
  public void Largest_size_accepted_under_the_memory_limit_renders()
  {
    // The square just inside the budget of a 512 MiB heap must render and save, not run out of memory.
    long pixels = ((512L << 20) - MemoryBudget.Baseline) / MemoryBudget.BytesPerPixel;
    int side = (int)Math.Sqrt(pixels);
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("bg.cs"), Background);
    var (code, stdout, error) = GrcisProcess.Run(dir.Path, SmallHeap, "render", "bg.cs", "--size", $"{side}x{side}", "-o", "big.png");
    Assert.True(code == 0, error);
    Assert.StartsWith($"wrote {dir.File("big.png")}: {side}x{side}", stdout);
  }

  static CliRun RenderMesh(TempDirectory dir, string objName)
  {
    File.WriteAllText(dir.File("mesh.cs"), ScriptCommandTests.SceneBody + $$"""

      SceneBrep brep = new SceneBrep();
      new WavefrontObj().ReadBrep(System.IO.Path.Combine(System.IO.Path.GetDirectoryName((string)context[PropertyName.CTX_SCRIPT_PATH])!, "{{objName}}"), brep);
      root.InsertChild(new TriangleMesh(brep), Matrix4d.Identity);
      """);
    return CliRun.Of(dir.Path, "render", "mesh.cs", "--size", "16x12", "-o", "out.png", "-q");
  }

  const string Triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

  [Theory]
  [InlineData("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n", "past.obj(4): vertex index 7 out of range")]
  [InlineData("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", "past.obj(4): vertex index -4 out of range")]
  [InlineData("v 0 0 0\nv 1 NaN 0\nv 0 1 0\nf 1 2 3\n", "past.obj(2): 'NaN' is not a number")]
  [InlineData("v 0 0 0\nv 1 0 1e999\nv 0 1 0\nf 1 2 3\n", "past.obj(2): '1e999' is not a number")]
  public void Bad_obj_values_name_the_file_and_line(string obj, string fragment)
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("past.obj"), obj);
    AssertRejected(RenderMesh(dir, "past.obj"), dir, ExitCodes.Failure, fragment);
  }

  static byte[] Gzip(string text)
  {
    var ms = new MemoryStream();
    using (var gz = new GZipStream(ms, CompressionLevel.Optimal, leaveOpen: true))
      gz.Write(System.Text.Encoding.ASCII.GetBytes(text));
    return ms.ToArray();
  }

  [Fact]
  public void Truncated_gzip_mesh_is_an_error_not_half_a_mesh()
  {
    using var dir = new TempDirectory();
    string many = string.Concat(Enumerable.Range(0, 2000).Select(i => $"v {i} 0 0\nv {i} 1 0\nv {i} 0 1\nf -3 -2 -1\n"));
    byte[] whole = Gzip(many);
    File.WriteAllBytes(dir.File("cut.obj.gz"), whole[..(whole.Length / 2)]);
    CliRun run = RenderMesh(dir, "cut.obj.gz");
    AssertRejected(run, dir, ExitCodes.Failure, "cut.obj.gz(", "truncated or corrupt");
  }

  [Fact]
  public void Gzip_mesh_that_is_not_gzip_is_an_error_at_line_one()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("plain.obj.gz"), Triangle + Triangle);
    AssertRejected(RenderMesh(dir, "plain.obj.gz"), dir, ExitCodes.Failure, "plain.obj.gz(1): corrupt compressed data");
  }

  [Fact]
  public void Whole_gzip_mesh_still_renders()
  {
    using var dir = new TempDirectory();
    File.WriteAllBytes(dir.File("ok.obj.gz"), Gzip(Triangle));
    CliRun run = RenderMesh(dir, "ok.obj.gz");
    Assert.True(run.ExitCode == 0, run.Error);
  }

  [UnixTheory]
  [InlineData("/dev/full")]
  [InlineData("/dev/null")]
  public void Device_as_output_is_refused_and_left_in_place(string device)
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", "--size", "8x6", "-o", device, "--format", "png", "-q");
    Assert.Equal(ExitCodes.Failure, run.ExitCode);
    Assert.Equal($"grcis: error: cannot write '{device}': it is a device, not a file (images are saved through a temporary file and a rename, which would replace it)", Assert.Single(run.ErrorLines));
    Assert.Equal(0, new FileInfo(device).Length);   // still the device (a saved PNG would have bytes)
  }

  [UnixFact]
  public void Link_to_a_device_as_output_is_refused()
  {
    using var dir = new TempDirectory();
    File.CreateSymbolicLink(dir.File("out.png"), "/dev/null");
    CliRun run = CliRun.Of(dir.Path, "render", "--size", "8x6", "-o", "out.png", "-q");
    Assert.Equal(ExitCodes.Failure, run.ExitCode);
    Assert.Contains("it is a device, not a file", Assert.Single(run.ErrorLines));
    Assert.Equal("/dev/null", new FileInfo(dir.File("out.png")).LinkTarget);
  }

  [Fact]
  public void Binary_file_as_script_is_one_line_not_hundreds_of_errors()
  {
    using var dir = new TempDirectory();
    byte[] data = new byte[4096];
    new Random(5).NextBytes(data);
    data[100] = 0;
    File.WriteAllBytes(dir.File("photo.cs"), data);
    AssertRejected(CliRun.Of(dir.Path, "render", "photo.cs", "-o", "x.png", "-q"), dir, ExitCodes.Failure,
      "'" + dir.File("photo.cs") + "' is not a C# scene script: it holds binary data");
  }

  [Fact]
  public void Many_compile_errors_show_the_first_ones_and_count_all()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("typos.cs"), string.Concat(Enumerable.Repeat("int x = ;\n", 40)));
    CliRun run = CliRun.Of(dir.Path, "render", "typos.cs", "-o", "x.png", "-q");
    Assert.Equal(ExitCodes.Failure, run.ExitCode);
    Assert.Equal(ScriptErrors.MaxErrorsShown, run.ErrorLines.Count(l => l.Contains(": error CS", StringComparison.Ordinal)));
    Assert.Matches(@"^grcis: error: scene script '.*typos\.cs' did not compile \((\d+) errors, the first 25 shown\)$", run.ErrorLines[^1]);
    Assert.DoesNotContain(dir.AllFiles(), f => f.EndsWith(".png", StringComparison.Ordinal));
  }

  [Fact]
  public void Directory_as_script_is_a_usage_error_that_says_so()
  {
    using var dir = new TempDirectory();
    Directory.CreateDirectory(dir.File("scenes.cs"));
    CliRun run = CliRun.Of(dir.Path, "render", "scenes.cs", "-o", "x.png", "-q");
    Assert.Equal(ExitCodes.Usage, run.ExitCode);
    Assert.Equal("grcis: error: scene script 'scenes.cs' is a directory; give a .cs file (a folder of classes is a --module)", Assert.Single(run.ErrorLines));
  }

  [Theory]
  [InlineData("FFD8FFE00010")]
  [InlineData("FFD8FFE000104A46494600")]
  public void Cut_JPEG_texture_is_one_error_naming_the_image_not_a_hang(string hex)
  {
    using var dir = new TempDirectory();
    File.WriteAllBytes(dir.File("t.jpg"), Convert.FromHexString(hex));
    File.WriteAllText(dir.File("textured.cs"), ScriptCommandTests.SceneBody + "\nroot.SetAttribute(PropertyName.TEXTURE, new ImageTexture(\"t.jpg\"));\n");
    var render = System.Threading.Tasks.Task.Run(() => CliRun.Of(dir.Path, "render", "textured.cs", "--size", "8x8", "-o", "x.png", "-q"));
    Assert.True(render.Wait(TimeSpan.FromSeconds(60)), "grcis render is still running after 60 s");
    AssertRejected(render.Result, dir, ExitCodes.Failure, "t.jpg: corrupt or unsupported image (");
  }

  [Theory]
  [InlineData("-o", "-o needs a file name (got an empty one)")]
  [InlineData("--noise", "--noise needs a file name (got an empty one)")]
  public void Empty_output_name_is_a_usage_error_not_the_default_name(string option, string expected)
  {
    using var dir = new TempDirectory();
    AssertRejected(CliRun.Of(dir.Path, "render", "Five balls", "--size", "8x8", option, "", "-q"), dir, ExitCodes.Usage, expected);
    Assert.Empty(dir.AllFiles());
  }

  [UnixFact]
  public void Dangling_link_as_script_is_a_usage_error_naming_its_target()
  {
    using var dir = new TempDirectory();
    File.CreateSymbolicLink(dir.File("scene.cs"), dir.File("moved-away.cs"));
    AssertRejected(CliRun.Of(dir.Path, "render", "scene.cs", "-o", "x.png", "-q"), dir, ExitCodes.Usage,
      "scene script 'scene.cs' not found: it is a link to '" + dir.File("moved-away.cs") + "', which does not exist");
  }

  [Fact]
  public void Directory_given_to_merge_is_a_usage_error_that_says_so()
  {
    using var dir = new TempDirectory();
    Directory.CreateDirectory(dir.File("parts"));
    CliRun run = CliRun.Of(dir.Path, "merge", "parts", "-o", "out.png");
    Assert.Equal(ExitCodes.Usage, run.ExitCode);
    Assert.Equal($"grcis: error: 'parts' is a directory; give the part files (e.g. '{Path.Combine("parts", "*.grcis-part")}')", Assert.Single(run.ErrorLines));
  }

  [Fact]
  public void Bench_mesh_that_is_not_obj_fails_naming_its_line_before_benchmarking()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("garbage.obj"), "v 0 0 0\nv 1 oops 0\n");
    CliRun run = CliRun.Of(dir.Path, "bench", "--quick", "--mesh", "garbage.obj");
    Assert.Equal(ExitCodes.Failure, run.ExitCode);
    Assert.Equal($"grcis: error: {dir.File("garbage.obj")}(2): 'oops' is not a number (in 'v')", Assert.Single(run.ErrorLines));
    Assert.Equal("", run.Out);
  }

  [Fact]
  public void Failed_image_write_leaves_no_noise_file_either()
  {
    using var dir = new TempDirectory();
    Directory.CreateDirectory(dir.File("out"));
    // The script (run twice: preprocessing and the regular call) puts a file in place of the image's folder after the
    // up-front checks, so the folder cannot be made again and the image's save fails.
    File.WriteAllText(dir.File("vanish.cs"), ScriptCommandTests.SceneBody +
      $"\nif (System.IO.Directory.Exists(@\"{dir.File("out")}\")) {{ System.IO.Directory.Delete(@\"{dir.File("out")}\", true); System.IO.File.WriteAllText(@\"{dir.File("out")}\", \"x\"); }}\n");
    CliRun run = CliRun.Of(dir.Path, "render", "vanish.cs", "--size", "8x8", "--spp", "4", "-o", "out/x.png", "--noise", "n.pfm", "-q");
    Assert.Equal(ExitCodes.Failure, run.ExitCode);
    string line = Assert.Single(run.ErrorLines);
    Assert.True(line.Contains("cannot write '" + dir.File("out/x.png") + "'", StringComparison.Ordinal), line);
    Assert.False(File.Exists(dir.File("n.pfm")));
  }
}
