using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using GrCis.Cli.Jobs;
using GrCis.TestSupport;

namespace GrCis.Cli.Tests;

/// <summary>
/// <c>--memory-limit</c>: a script that keeps allocating stops with <c>OutOfMemoryException</c> at its line (exit 1)
/// within seconds, instead of growing until the kernel kills grcis (exit 137, nothing printed). The limit is set on the
/// process, so the tests that reach it run grcis as a process.
/// </summary>
public class MemoryLimitTests
{
  const string Hoarder = StuckScripts.Camera + """

    var hoard = new List<byte[]>();
    while (true)
      hoard.Add(new byte[16 << 20]);
    """;

  static void AssertOutOfMemory(TempDirectory dir, string script, int line, IDictionary<string, string>? env, params string[] args)
  {
    var clock = Stopwatch.StartNew();
    using Process p = GrcisProcess.Start(dir.Path, env, args);
    (int code, string output, string error) = GrcisProcess.Finish(p);
    Assert.True(code == ExitCodes.Failure, $"exit {code}\n{output}\n{error}");
    Assert.True(clock.Elapsed < TimeSpan.FromSeconds(60), $"took {clock.Elapsed.TotalSeconds:0} s");
    string last = error.TrimEnd().Split('\n')[^1];
    Assert.StartsWith($"grcis: error: {dir.File(script)}({line},", last);
    Assert.Contains("runtime error: OutOfMemoryException", last);
    Assert.DoesNotContain(dir.AllFiles(), f => f.EndsWith(".png", StringComparison.Ordinal));
  }

  [Fact]
  public void A_script_that_allocates_without_end_stops_at_its_line_under_the_limit()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("hog.cs"), Hoarder);
    AssertOutOfMemory(dir, "hog.cs", 6, null, "render", "hog.cs", "--memory-limit", "200M", "-o", "out.png", "-q");
  }

  [Fact]
  public void A_texture_that_allocates_while_rendering_stops_at_its_line_under_the_limit()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("texture.cs"), StuckScripts.Camera + """

      var root = new CSGInnerNode(SetOperation.Union);
      var s = new Sphere();
      s.SetAttribute(PropertyName.TEXTURE, new Hog());
      root.InsertChild(s, Matrix4d.Identity);
      scene.Intersectable = root;
      class Hog : ITexture
      {
        static readonly List<byte[]> hoard = new();
        public long Apply(Intersection inter)
        {
          lock (hoard) hoard.Add(new byte[16 << 20]);
          return 0;
        }
      }
      """);
    AssertOutOfMemory(dir, "texture.cs", 14, null, "animate", "texture.cs", "--memory-limit", "300M", "-o", "f#.png", "--to", "0.08",
                      "-s", "32x24", "-q");
  }

  [Fact]
  public void A_limit_the_environment_set_is_kept_by_default()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("hog.cs"), Hoarder);
    AssertOutOfMemory(dir, "hog.cs", 6, new Dictionary<string, string> { ["DOTNET_GCHeapHardLimit"] = "0xC800000" }, // 200 MiB
                      "render", "hog.cs", "-o", "out.png", "-q");
  }

  [Theory]
  [InlineData("2X")]
  [InlineData("-1G")]
  [InlineData("150%")]
  [InlineData("1M")]
  [InlineData("")]
  public void A_malformed_or_too_small_limit_is_a_usage_error(string value)
  {
    using var dir = new TempDirectory();
    foreach (string command in new[] { "render", "animate" })
    {
      CliRun run = CliRun.Of(dir.Path, command, "Five balls", "--memory-limit", value, "-o", command == "render" ? "x.png" : "f#.png");
      Assert.Equal(ExitCodes.Usage, run.ExitCode);
      Assert.StartsWith($"grcis: error: invalid --memory-limit '{value}'", run.Error);
      Assert.Empty(dir.AllFiles());
    }
  }

  [Theory]
  [InlineData("4G", 4L << 30)]
  [InlineData("512M", 512L << 20)]
  [InlineData("512MiB", 512L << 20)]
  [InlineData("1.5g", 3L << 29)]
  [InlineData("100000000", 100_000_000L)]
  [InlineData("50%", 8L << 30)]
  [InlineData("0", 0L)]
  [InlineData("none", 0L)]
  [InlineData("NONE", 0L)]
  public void Limits_read_as_sizes_shares_or_none(string text, long bytes) =>
    Assert.Equal(bytes, MemoryLimit.Resolve(text, 16L << 30, setByEnvironment: false));

  [Fact]
  public void The_default_is_three_quarters_of_the_memory_unless_the_environment_set_a_limit()
  {
    Assert.Equal(12L << 30, MemoryLimit.Resolve(null, 16L << 30, setByEnvironment: false));
    Assert.Equal(0L, MemoryLimit.Resolve(null, 16L << 30, setByEnvironment: true));
    Assert.Equal(1L << 30, MemoryLimit.Resolve("1G", 16L << 30, setByEnvironment: true));
  }
}
