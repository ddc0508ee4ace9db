using System;
using System.IO;
using System.Linq;

namespace GrCis.Cli.Tests;

/// <summary>
/// <c>render --tiles i/n</c> and <c>merge</c>: the merged PNG and PFM are the one-process render's
/// files byte for byte for every renderer, and every set of parts that does not make one image is
/// refused with one line, exit code 1 and no output file.
/// </summary>
public class TilesMergeTests
{
  /// <summary>Orbit (animated) with motion blur through the script's image function, sampled adaptively.</summary>
  internal static string BlurScript(TempDirectory dir)
  {
    string path = dir.File("blur.cs");
    File.WriteAllText(path, File.ReadAllText(RepoPaths.Script("Orbit.cs")) + """

      context[PropertyName.CTX_ALGORITHM] = new MotionBlurImageFunction(new RayTracing()) { FrameTime = 1.5, Shutter = 1 };
      context[PropertyName.CTX_SYNTHESIZER] = new AdaptiveSupersampling { Supersampling = 16 };
      """);
    return path;
  }

  static void Ok(CliRun run) => Assert.True(run.ExitCode == 0, run.Error);

  /// <summary>Renders whole (PNG and PFM) and in <paramref name="count"/> parts, merges both ways, compares the files.</summary>
  static void AssertMergeEqualsOneProcess(TempDirectory dir, string[] render, int count)
  {
    Ok(CliRun.Of(dir.Path, [.. render, "-o", "whole.png", "-q"]));
    Ok(CliRun.Of(dir.Path, [.. render, "-o", "whole.pfm", "-q", "--threads", "1"]));
    for (int i = 0; i < count; i++)
      // Alternate thread counts: parts from differently sized machines must still fit.
      Ok(CliRun.Of(dir.Path, [.. render, "--tiles", $"{i}/{count}", "-o", $"p{i}.grcis-part", "-q", "--threads", (1 + i % 2).ToString()]));
    string[] parts = Enumerable.Range(0, count).Reverse().Select(i => $"p{i}.grcis-part").ToArray();
    Ok(CliRun.Of(dir.Path, ["merge", .. parts, "-o", "merged.png"]));
    Ok(CliRun.Of(dir.Path, ["merge", .. parts, "-o", "merged.pfm"]));
    Assert.Equal(File.ReadAllBytes(dir.File("whole.png")), File.ReadAllBytes(dir.File("merged.png")));
    Assert.Equal(File.ReadAllBytes(dir.File("whole.pfm")), File.ReadAllBytes(dir.File("merged.pfm")));
  }

  [Fact]
  public void Merged_parts_of_a_pixel_centre_render_are_the_one_process_files()
  {
    using var dir = new TempDirectory();
    AssertMergeEqualsOneProcess(dir, ["render", "Five balls", "--size", "100x70"], 3);
  }

  [Fact]
  public void Merged_parts_of_a_jittered_supersampled_render_are_the_one_process_files()
  {
    using var dir = new TempDirectory();
    AssertMergeEqualsOneProcess(dir, ["render", "Two spheres", "--size", "90x65", "--spp", "9", "--seed", "7"], 4);
  }

  [Fact]
  public void Merged_parts_of_a_script_with_motion_blur_and_adaptive_sampling_are_the_one_process_files()
  {
    using var dir = new TempDirectory();
    AssertMergeEqualsOneProcess(dir, ["render", BlurScript(dir), "--size", "64x48", "--time", "1.5"], 2);
  }

  [Fact]
  public void Merged_parts_of_a_script_with_its_own_supersampling_are_the_one_process_files()
  {
    using var dir = new TempDirectory();
    string script = dir.File("ss.cs");
    File.WriteAllText(script, ScriptCommandTests.SceneBody +
      "context[PropertyName.CTX_SYNTHESIZER] = new SupersamplingImageSynthesizer { Supersampling = 4 };\n");
    AssertMergeEqualsOneProcess(dir, ["render", script, "--size", "70x40"], 5);
  }

  [Fact]
  public void A_single_part_holds_the_whole_image()
  {
    using var dir = new TempDirectory();
    AssertMergeEqualsOneProcess(dir, ["render", "Cubes", "--size", "40x30"], 1);
  }

  /// <summary>Three parts of a 64x48 render with seed 1; returns the render arguments.</summary>
  static string[] ThreeParts(TempDirectory dir)
  {
    string[] render = ["render", "Five balls", "--size", "64x48", "--seed", "1", "-q"];
    for (int i = 0; i < 3; i++)
      Ok(CliRun.Of(dir.Path, [.. render, "--tiles", $"{i}/3", "-o", $"p{i}.grcis-part"]));
    return render;
  }

  static void AssertRefused(TempDirectory dir, string expected, params string[] parts)
  {
    CliRun run = CliRun.Of(dir.Path, ["merge", .. parts, "-o", "out.png"]);
    Assert.Equal(ExitCodes.Failure, run.ExitCode);
    string line = Assert.Single(run.ErrorLines);
    Assert.StartsWith("grcis: error: ", line);
    Assert.Contains(expected, line);
    Assert.False(File.Exists(dir.File("out.png")));
    Assert.DoesNotContain(dir.AllFiles(), f => f.Contains(".tmp-"));
  }

  [Fact]
  public void Merge_of_an_incomplete_set_is_refused_naming_the_missing_part()
  {
    using var dir = new TempDirectory();
    ThreeParts(dir);
    AssertRefused(dir, "incomplete: 1 of 3 parts missing (1/3)", "p0.grcis-part", "p2.grcis-part");
  }

  [Fact]
  public void Merge_of_overlapping_parts_is_refused()
  {
    using var dir = new TempDirectory();
    ThreeParts(dir);
    File.Copy(dir.File("p1.grcis-part"), dir.File("copy.grcis-part"));
    AssertRefused(dir, "overlapping parts: 'p1.grcis-part' and 'copy.grcis-part' are both part 1/3",
      "p0.grcis-part", "p1.grcis-part", "copy.grcis-part", "p2.grcis-part");
  }

  [Fact]
  public void Merge_of_a_part_with_damaged_or_absurd_pixels_is_refused_naming_it()
  {
    using var dir = new TempDirectory();
    ThreeParts(dir);
    byte[] p2 = File.ReadAllBytes(dir.File("p2.grcis-part"));
    p2[^100] ^= 0x08;
    File.WriteAllBytes(dir.File("flipped.grcis-part"), p2);
    AssertRefused(dir, dir.File("flipped.grcis-part") + ": pixel data damaged (CRC-32", "p0.grcis-part", "p1.grcis-part", "flipped.grcis-part");

    // Re-saved with a valid checksum around a value no render gives.
    (Rendering.Parts.PartHeader h, float[] samples) = Rendering.Parts.PartFile.Load(dir.File("p2.grcis-part"));
    var image = new Rendering.Imaging.FloatImage(h.Width, h.Height);
    Rendering.Parts.PartFile.Place(h, samples, image);
    Array.Fill(image.Data, -1e30f);
    Rendering.Parts.PartFile.Save(dir.File("forged.grcis-part"), h, image);
    AssertRefused(dir, dir.File("forged.grcis-part") + ": pixel (", "p0.grcis-part", "p1.grcis-part", "forged.grcis-part");
  }

  [Theory]
  [InlineData("--seed 2", "seed (1 vs 2)")]
  [InlineData("--size 64x40", "size (64x48 vs 64x40)")]
  [InlineData("--spp 4", "spp (1 vs 4)")]
  [InlineData("--no-shadows", "scene settings")]
  [InlineData("--gamma 1", "gamma (2.2 vs 1)")]
  [InlineData("scene=Cubes", "scene (Five balls vs Cubes)")]
  [InlineData("count=4", "part count (3 vs 4)")]
  public void Merge_of_parts_from_different_renders_is_refused_naming_what_differs(string change, string expected)
  {
    using var dir = new TempDirectory();
    string[] render = ThreeParts(dir);
    string tiles = "2/3";
    if (change.StartsWith("scene="))
      render[1] = change["scene=".Length..];
    else if (change == "count=4")
      tiles = "2/4";
    else if (Array.IndexOf(render, change.Split(' ')[0]) is int at and >= 0)
      render[at + 1] = change.Split(' ')[1];   // same option, other value
    else
      render = [.. render, .. change.Split(' ')];
    Ok(CliRun.Of(dir.Path, [.. render, "--tiles", tiles, "-o", "odd.grcis-part"]));
    AssertRefused(dir, $"'odd.grcis-part' is not from the same render as 'p0.grcis-part': {expected} differ",
      "p0.grcis-part", "p1.grcis-part", "odd.grcis-part");
  }

  [Fact]
  public void Merge_of_parts_of_an_edited_script_is_refused()
  {
    using var dir = new TempDirectory();
    string script = dir.File("s.cs");
    File.WriteAllText(script, ScriptCommandTests.SceneBody);
    Ok(CliRun.Of(dir.Path, "render", script, "--size", "32x32", "--tiles", "0/2", "-o", "a.grcis-part", "-q"));
    File.AppendAllText(script, "\n// edited\n");
    Ok(CliRun.Of(dir.Path, "render", script, "--size", "32x32", "--tiles", "1/2", "-o", "b.grcis-part", "-q"));
    AssertRefused(dir, "scene settings differ", "a.grcis-part", "b.grcis-part");
  }

  [Fact]
  public void Merge_of_a_truncated_or_foreign_file_is_refused_naming_it()
  {
    using var dir = new TempDirectory();
    ThreeParts(dir);
    byte[] p2 = File.ReadAllBytes(dir.File("p2.grcis-part"));
    File.WriteAllBytes(dir.File("cut.grcis-part"), p2[..^4]);
    AssertRefused(dir, "cut.grcis-part: pixel data truncated", "p0.grcis-part", "p1.grcis-part", "cut.grcis-part");
    File.WriteAllText(dir.File("x.grcis-part"), "hello");
    AssertRefused(dir, "x.grcis-part: not a grcis part file", "p0.grcis-part", "p1.grcis-part", "x.grcis-part");
    AssertRefused(dir, "cannot read 'none.grcis-part'", "p0.grcis-part", "p1.grcis-part", "none.grcis-part");
  }

  [Theory]
  [InlineData("3/3", "invalid --tiles '3/3'")]
  [InlineData("a/3", "invalid --tiles 'a/3'")]
  public void Bad_tiles_value_is_a_usage_error_before_rendering(string tiles, string expected)
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", "--size", "16x16", "--tiles", tiles, "-o", "p.grcis-part");
    Assert.Equal(ExitCodes.Usage, run.ExitCode);
    Assert.Contains(expected, Assert.Single(run.ErrorLines));
    Assert.Empty(dir.AllFiles());
  }

  [Fact]
  public void Tiles_need_a_part_file_and_a_part_file_needs_tiles()
  {
    using var dir = new TempDirectory();
    CliRun png = CliRun.Of(dir.Path, "render", "--size", "16x16", "--tiles", "0/2", "-o", "p.png");
    Assert.Equal(ExitCodes.Usage, png.ExitCode);
    Assert.Contains("name it *.grcis-part", png.Error);
    CliRun part = CliRun.Of(dir.Path, "render", "--size", "16x16", "-o", "p.grcis-part");
    Assert.Equal(ExitCodes.Usage, part.ExitCode);
    Assert.Contains("only with --tiles", part.Error);
    Assert.Empty(dir.AllFiles());
  }

  [Fact]
  public void Merge_needs_an_image_output_and_is_a_usage_error_without_one()
  {
    using var dir = new TempDirectory();
    ThreeParts(dir);
    string[] parts = ["p0.grcis-part", "p1.grcis-part", "p2.grcis-part"];
    CliRun none = CliRun.Of(dir.Path, ["merge", .. parts]);
    Assert.Equal(ExitCodes.Usage, none.ExitCode);
    Assert.Contains("'--output' is required", Assert.Single(none.ErrorLines));
    CliRun part = CliRun.Of(dir.Path, ["merge", .. parts, "-o", "all.grcis-part"]);
    Assert.Equal(ExitCodes.Usage, part.ExitCode);
    Assert.Contains("not a part file", Assert.Single(part.ErrorLines));
    Assert.Equal(3, dir.AllFiles().Length);
  }

  [Fact]
  public void Part_without_output_name_gets_index_and_count_in_its_default_name()
  {
    using var dir = new TempDirectory();
    Ok(CliRun.Of(dir.Path, "render", "Cubes", "--size", "16x16", "--tiles", "1/2", "-q"));
    Assert.Equal(new[] { dir.File("cubes-1of2.grcis-part") }, dir.AllFiles());
  }
}
