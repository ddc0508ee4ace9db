using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Security.Cryptography;
using System.Text;
using Rendering;

namespace GrCis.Cli.Tests;

/// <summary>
/// Images do not change unnoticed: every built-in scene and every script in scripts/ is rendered
/// through <c>grcis render</c> (64×48, 4 spp with jitter, seed 5, two threads) to PFM, and the SHA-256
/// of its linear pixels is compared with Data/image-hashes.txt. A refactoring must keep every line;
/// an intended change of a picture is re-recorded with <c>GRCIS_RECORD_HASHES=1</c> and reviewed in the diff.
/// </summary>
public class ImageHashTests
{
  const string RecordVariable = "GRCIS_RECORD_HASHES";

  static string HashFile => Path.Combine(RepoPaths.Root, "tests", "GrCis.Cli.Tests", "Data", "image-hashes.txt");

  public static IEnumerable<object[]> Scenes()
  {
    foreach (string name in Rendering.Scenes.Names)
      yield return new object[] { name };
    foreach (string file in Directory.GetFiles(RepoPaths.Scripts, "*.cs").Select(Path.GetFileName).OrderBy(f => f, StringComparer.Ordinal))
      yield return new object[] { "scripts/" + file };
  }

  static Dictionary<string, string> Recorded() =>
    File.ReadAllLines(HashFile)
      .Where(l => l.Length > 0 && !l.StartsWith('#'))
      .Select(l => l.Split('\t'))
      .ToDictionary(p => p[0], p => p[1], StringComparer.Ordinal);

  /// <summary>SHA-256 of the pixel data of a PFM file (the header's formatting is not part of the picture).</summary>
  static string PixelHash(string pfm)
  {
    byte[] bytes = File.ReadAllBytes(pfm);
    int newlines = 0, start = 0;
    while (newlines < 3)
      if (bytes[start++] == (byte)'\n')
        newlines++;
    return Convert.ToHexString(SHA256.HashData(bytes.AsSpan(start)))[..32].ToLowerInvariant();
  }

  [Theory]
  [MemberData(nameof(Scenes))]
  public void Rendered_pixels_match_the_recorded_hash(string scene)
  {
    using var dir = new TempDirectory();
    string argument = scene.StartsWith("scripts/", StringComparison.Ordinal) ? RepoPaths.Script(scene["scripts/".Length..]) : scene;
    CliRun run = CliRun.Of(dir.Path, "render", argument, "-o", "out.pfm", "--size", "64x48", "--spp", "4", "--seed", "5", "--threads", "2", "-q");
    Assert.True(run.ExitCode == 0, run.Error);
    string hash = PixelHash(dir.File("out.pfm"));

    if (Environment.GetEnvironmentVariable(RecordVariable) == "1")
    {
      lock (typeof(ImageHashTests))
      {
        var all = File.Exists(HashFile) ? Recorded() : new Dictionary<string, string>();
        all[scene] = hash;
        var text = new StringBuilder("# scene\tSHA-256 (first 128 bits) of the PFM pixels of: grcis render <scene> --size 64x48 --spp 4 --seed 5 --threads 2\n");
        foreach (var (k, v) in all.OrderBy(p => p.Key, StringComparer.Ordinal))
          text.Append(k).Append('\t').Append(v).Append('\n');
        File.WriteAllText(HashFile, text.ToString());
      }
      return;
    }
    Assert.True(Recorded().TryGetValue(scene, out string? expected), $"{scene}: no recorded hash; record it with {RecordVariable}=1 (got {hash})");
    Assert.True(expected == hash, $"{scene}: the picture changed (recorded {expected}, now {hash}); if intended, re-record with {RecordVariable}=1");
  }

  [Fact]
  public void Every_recorded_scene_still_exists()
  {
    var present = Scenes().Select(o => (string)o[0]).ToHashSet(StringComparer.Ordinal);
    Assert.Empty(Recorded().Keys.Where(k => !present.Contains(k)));
  }
}
