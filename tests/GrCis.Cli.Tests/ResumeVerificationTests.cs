using System;
using System.Buffers.Binary;
using System.IO;
using System.Linq;
using System.Text;
using GrCis.Cli.Animation;
using Rendering.Imaging;

namespace GrCis.Cli.Tests;

/// <summary>
/// <c>animate --resume</c> keeps a frame only when it is a whole frame of this very render: intact chunks and
/// image data, its fingerprint equal to this render's, its pixels matching their checksum. Everything else in
/// the folder (damaged files, frames of another scene, spp, seed or range, files without a fingerprint) is
/// rendered again and counted in one line.
/// </summary>
public class ResumeVerificationTests
{
  static readonly string[] Common = ["animate", "test-moving", "--fps", "1", "--size", "20x16"];

  /// <summary>The common command at 4 spp unless <paramref name="extra"/> says otherwise.</summary>
  static CliRun Animate(TempDirectory dir, params string[] extra) =>
    AnimateRun.Of(dir.Path, [.. Common, "-o", "f/m#.png", .. extra.Contains("--spp") ? [] : new[] { "--spp", "4" }, .. extra]);

  /// <summary>Renders the five frames once, checks the run, and returns their bytes.</summary>
  static (string Name, byte[] Bytes)[] RenderAll(TempDirectory dir, params string[] extra)
  {
    CliRun run = Animate(dir, extra);
    Assert.True(run.ExitCode == 0, run.Error);
    var frames = AnimateRun.Snapshot(dir.File("f"));
    Assert.Equal(5, frames.Length);
    return frames;
  }

  /// <summary>Offset of the first byte of the first IDAT chunk's data.</summary>
  static int IdatData(byte[] png)
  {
    int at = 8;
    while (Encoding.ASCII.GetString(png, at + 4, 4) != "IDAT")
      at += 12 + BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(at));
    return at + 8;
  }

  /// <summary>Sets every frame's time stamp far in the past, so a frame rewritten by the next run shows.</summary>
  static void Age(TempDirectory dir)
  {
    foreach (string f in Directory.GetFiles(dir.File("f")))
      File.SetLastWriteTimeUtc(f, new DateTime(2001, 1, 1, 0, 0, 0, DateTimeKind.Utc));
  }

  static DateTime Stamp(TempDirectory dir, int k) => File.GetLastWriteTimeUtc(dir.File($"f/m{k}.png"));

  [Fact]
  public void Frames_of_this_render_are_kept_untouched()
  {
    using var dir = new TempDirectory();
    var first = RenderAll(dir);
    Age(dir);

    CliRun again = Animate(dir, "--resume");
    Assert.True(again.ExitCode == 0, again.Error);
    Assert.Contains("wrote 0 frames (5 complete, skipped)", again.Out);
    Assert.DoesNotContain("redid", again.Out);
    Assert.DoesNotContain("redoing", again.Error);
    Assert.All(Enumerable.Range(0, 5), k => Assert.Equal(2001, Stamp(dir, k).Year));
    AnimateRun.AssertSameFiles(first, AnimateRun.Snapshot(dir.File("f")));
  }

  [Fact]
  public void A_frame_carries_a_readable_fingerprint_of_its_render()
  {
    using var dir = new TempDirectory();
    RenderAll(dir, "--seed", "7");
    CheckedPng png = CheckedPng.Read(dir.File("f/m3.png"));
    string text = png.Text[FrameFingerprint.Keyword];
    string[] lines = text.Split('\n');
    Assert.Equal("grcis-frame 1", lines[0]);
    Assert.Contains("scene test-moving", lines);
    Assert.Contains("size 20x16", lines);
    Assert.Contains("spp 4", lines);
    Assert.Contains("seed 7", lines);
    Assert.Contains("frame 3", lines);
    Assert.Contains("time 3", lines);
    Assert.Contains("fps 1", lines);
    Assert.Matches("^render [0-9a-f]{64}$", lines.Single(l => l.StartsWith("render ", StringComparison.Ordinal)));
    Assert.Equal("pixels " + FrameFingerprint.PixelHash(png.Decode()), lines[^1]);
    // The text is metadata only: the pixels are those any PNG reader sees.
    Assert.True(png.Decode().ContentEquals(PngFile.Load(dir.File("f/m3.png"))));
  }

  [Fact]
  public void A_one_bit_flip_in_the_image_data_is_found_and_the_frame_rendered_again()
  {
    using var dir = new TempDirectory();
    var first = RenderAll(dir);
    byte[] damaged = (byte[])first[2].Bytes.Clone();
    damaged[IdatData(damaged) + 10] ^= 0x08;
    File.WriteAllBytes(dir.File("f/m2.png"), damaged);
    Age(dir);

    CliRun resumed = Animate(dir, "--resume");
    Assert.True(resumed.ExitCode == 0, resumed.Error);
    Assert.Contains("wrote 1 frame (4 complete, skipped)", resumed.Out);
    Assert.Contains("redid 1 frame: 1 corrupt (m2.png: CRC mismatch in chunk IDAT", resumed.Out);
    Assert.Contains("grcis: note: --resume is redoing 1 frame: 1 corrupt", resumed.Error);
    Assert.Equal(2001, Stamp(dir, 1).Year);
    AnimateRun.AssertSameFiles(first, AnimateRun.Snapshot(dir.File("f")));
  }

  [Fact]
  public void Truncated_empty_and_garbage_frames_are_rendered_again()
  {
    using var dir = new TempDirectory();
    var first = RenderAll(dir);
    File.WriteAllBytes(dir.File("f/m0.png"), first[0].Bytes[..^20]);   // IEND and some data cut off
    File.WriteAllBytes(dir.File("f/m1.png"), []);
    File.WriteAllBytes(dir.File("f/m4.png"), Enumerable.Range(0, 500).Select(i => (byte)(i * 7)).ToArray());

    CliRun resumed = Animate(dir, "--resume");
    Assert.True(resumed.ExitCode == 0, resumed.Error);
    Assert.Contains("wrote 3 frames (2 complete, skipped)", resumed.Out);
    Assert.Contains("redid 3 frames: 3 corrupt (m0.png: cut off", resumed.Out);
    Assert.Contains("m1.png: empty", resumed.Out);
    Assert.Contains("m4.png: not a PNG file", resumed.Out);
    AnimateRun.AssertSameFiles(first, AnimateRun.Snapshot(dir.File("f")));
  }

  [Theory]
  [InlineData("--spp", "9", "different spp")]
  [InlineData("--seed", "3", "different seed")]
  [InlineData("--gamma", "1", "different script or settings")]
  [InlineData("--to", "3", "different --from/--to/--fps")]
  [InlineData("--shutter", "0.5", "different shutter")]
  public void Frames_of_another_render_in_the_folder_are_rendered_again(string option, string value, string why)
  {
    using var dir = new TempDirectory();
    CliRun other = Animate(dir, option, value);
    Assert.True(other.ExitCode == 0, other.Error);
    using var reference = new TempDirectory();
    var expected = RenderAll(reference);

    CliRun resumed = Animate(dir, "--resume");
    Assert.True(resumed.ExitCode == 0, resumed.Error);
    int redone = option == "--to" ? 4 : 5;   // --to 3 wrote frames 0-3 only; frame 4 is missing, not redone
    Assert.Contains($"wrote 5 frames", resumed.Out);
    Assert.Contains($"redid {redone} frames: {redone} from another render ({why})", resumed.Out);
    AnimateRun.AssertSameFiles(expected, AnimateRun.Snapshot(dir.File("f")));
  }

  [Fact]
  public void Frames_of_another_scene_or_of_another_frame_number_are_rendered_again()
  {
    using var dir = new TempDirectory();
    var expected = RenderAll(dir);
    // A frame of another scene, and a frame moved to another number.
    Assert.Equal(0, AnimateRun.Of(dir.Path, "animate", "test-clock", "--fps", "1", "--to", "4", "--frames", "0-0", "--size", "20x16", "--spp", "4", "-o", "other#.png", "-q").ExitCode);
    File.Move(dir.File("other0.png"), dir.File("f/m0.png"), overwrite: true);
    File.Copy(dir.File("f/m3.png"), dir.File("f/m4.png"), overwrite: true);

    CliRun resumed = Animate(dir, "--resume");
    Assert.True(resumed.ExitCode == 0, resumed.Error);
    Assert.Contains("redid 2 frames: 2 from another render (different scene, frame number)", resumed.Out);
    AnimateRun.AssertSameFiles(expected, AnimateRun.Snapshot(dir.File("f")));
  }

  [Fact]
  public void A_frame_without_a_fingerprint_is_rendered_again_and_said_so()
  {
    using var dir = new TempDirectory();
    var expected = RenderAll(dir);
    // The same pixels saved by another program: no fingerprint, so nothing vouches for them.
    PngFile.Save(dir.File("f/m1.png"), PngFile.Load(dir.File("f/m1.png")));

    CliRun resumed = Animate(dir, "--resume");
    Assert.True(resumed.ExitCode == 0, resumed.Error);
    Assert.Contains("redid 1 frame: 1 without a fingerprint (written by an older grcis or another program)", resumed.Out);
    AnimateRun.AssertSameFiles(expected, AnimateRun.Snapshot(dir.File("f")));
  }

  [Fact]
  public void Pixels_changed_under_an_intact_fingerprint_fail_their_checksum()
  {
    using var dir = new TempDirectory();
    var expected = RenderAll(dir);
    // Another picture re-encoded with frame 2's own fingerprint: every CRC and the zlib stream are valid.
    CheckedPng png = CheckedPng.Read(dir.File("f/m2.png"));
    Rgb8Image pixels = png.Decode();
    pixels.Data[5] ^= 1;
    PngFile.Save(dir.File("f/m2.png"), pixels, [new(FrameFingerprint.Keyword, png.Text[FrameFingerprint.Keyword])]);

    CliRun resumed = Animate(dir, "--resume");
    Assert.True(resumed.ExitCode == 0, resumed.Error);
    Assert.Contains("redid 1 frame: 1 corrupt (m2.png: its pixels do not match their checksum)", resumed.Out);
    AnimateRun.AssertSameFiles(expected, AnimateRun.Snapshot(dir.File("f")));
  }

  [Fact]
  public void Shards_then_a_resume_give_the_bytes_of_one_process()
  {
    using var dir = new TempDirectory();
    var one = RenderAll(dir);
    Directory.Delete(dir.File("f"), recursive: true);

    for (int i = 0; i < 2; i++)
    {
      CliRun shard = Animate(dir, "--shard", $"{i}/2", "--resume", "--threads", (i + 1).ToString());
      Assert.True(shard.ExitCode == 0, shard.Error);
    }
    Age(dir);
    CliRun final = Animate(dir, "--resume", "--parallel", "tiles");
    Assert.True(final.ExitCode == 0, final.Error);
    Assert.Contains("wrote 0 frames (5 complete, skipped)", final.Out);
    Assert.All(Enumerable.Range(0, 5), k => Assert.Equal(2001, Stamp(dir, k).Year));
    AnimateRun.AssertSameFiles(one, AnimateRun.Snapshot(dir.File("f")));
  }

  [Fact]
  public void An_edited_script_makes_its_old_frames_another_render()
  {
    using var dir = new TempDirectory();
    string script = ScriptCommandTests.SceneBody;
    File.WriteAllText(dir.File("S.cs"), script);
    string[] args = ["animate", "S.cs", "--to", "1", "--fps", "1", "--size", "8x6", "-o", "s/f#.png", "--resume"];
    Assert.Equal(0, CliRun.Of(dir.Path, args).ExitCode);
    CliRun same = CliRun.Of(dir.Path, args);
    Assert.True(same.ExitCode == 0, same.Error);
    Assert.Contains("wrote 0 frames (2 complete, skipped)", same.Out);

    File.WriteAllText(dir.File("S.cs"), script + "// edited\n");
    CliRun edited = CliRun.Of(dir.Path, args);
    Assert.True(edited.ExitCode == 0, edited.Error);
    Assert.Contains("redid 2 frames: 2 from another render (different script or settings)", edited.Out);
  }
}
