using System;
using System.Linq;
using Rendering.Imaging;

namespace GrCis.Cli.Tests;

/// <summary><c>grcis render --noise FILE.pfm</c>: each pixel's estimated standard error beside the image.</summary>
public class NoiseOptionTests
{
  [Fact]
  public void Noise_file_holds_each_pixels_standard_error_and_the_summary_its_rmse()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", "Five balls", "--size", "40x30", "--spp", "16", "--algorithm", "path", "-o", "balls.pfm",
      "--noise", "noise.pfm");

    Assert.Equal(0, run.ExitCode);
    FloatImage noise = PfmReader.Load(dir.File("noise.pfm"));
    Assert.Equal((40, 30, 1), (noise.Width, noise.Height, noise.Bands));
    Assert.All(noise.Data, v => Assert.True(float.IsFinite(v) && v >= 0f, $"standard error {v}"));
    Assert.Contains(noise.Data, v => v > 0f);
    // The summary's RMSE is the root mean of the file's squared errors.
    double rmse = Math.Sqrt(noise.Data.Average(v => (double)v * v));
    string line = run.Out.Trim();
    string printed = line[(line.IndexOf("noise ", StringComparison.Ordinal) + 6)..].Split(' ')[0];
    Assert.Equal(rmse, double.Parse(printed, System.Globalization.CultureInfo.InvariantCulture), rmse * 1e-3 + 1e-4);
  }

  [Fact]
  public void At_one_sample_the_noise_file_is_nan_and_a_warning_says_why()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", "Five balls", "--size", "20x15", "-o", "b.png", "--noise", "n.pfm");
    Assert.Equal(0, run.ExitCode);
    Assert.Contains("no noise estimate at 1 spp", run.Error);
    Assert.All(PfmReader.Load(dir.File("n.pfm")).Data, v => Assert.True(float.IsNaN(v)));
    Assert.DoesNotContain("noise", run.Out);
  }

  [Theory]
  [InlineData("n.png", "name it *.pfm")]
  [InlineData("b.pfm", "the image's own output file")]
  public void A_bad_noise_file_is_refused_before_rendering_and_nothing_is_written(string file, string message)
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", "Five balls", "--size", "20x15", "--spp", "4", "-o", "b.pfm", "--noise", file, "-q");
    Assert.NotEqual(0, run.ExitCode);
    Assert.Contains(message, run.Error);
    Assert.Empty(dir.AllFiles());
  }

  [Fact]
  public void Noise_is_not_written_for_a_part()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", "Five balls", "--size", "20x15", "--tiles", "1/2", "--noise", "n.pfm", "-q");
    Assert.NotEqual(0, run.ExitCode);
    Assert.Contains("--noise", run.Error);
    Assert.Empty(dir.AllFiles());
  }
}
