using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using GrCis.Cli.Jobs;
using GrCis.Hosting;
using Rendering;
using Rendering.Imaging;

namespace GrCis.Cli.Animation;

/// <summary>
/// The fingerprint an animation frame carries in its PNG (an <c>iTXt</c> chunk, keyword <see cref="Keyword"/>):
/// the render that made it (<see cref="RenderIdentity"/>'s hash, and for people the scene, size, spp and seed),
/// the timeline, the shutter, the frame's number and time, and the SHA-256 of its pixels. <c>--resume</c>
/// keeps a frame only when all of it equals this render's and the decoded pixels match their checksum.
/// Threads, <c>--parallel</c>, <c>--frames</c> and <c>--shard</c> are not in it: they do not change a
/// frame, so the frames of shards and of one process are the same bytes.
/// </summary>
public sealed class FrameFingerprint
{
  /// <summary>The PNG text keyword of the fingerprint.</summary>
  public const string Keyword = "GrCis frame";

  const string FormatLine = "grcis-frame 1";
  const string PixelsKey = "pixels";

  readonly string scene, render;
  readonly ImageSize size;
  readonly int samplesPerPixel;
  readonly long seed;
  readonly AnimationTimeline timeline;
  readonly double shutter;

  /// <param name="scene">The scene's name, for people (the hash decides).</param>
  /// <param name="renderHash">The hash of <see cref="RenderIdentity.Describe"/>, shared by all frames.</param>
  public FrameFingerprint(string scene, string renderHash, ImageSize size, int samplesPerPixel, long seed, AnimationTimeline timeline, double shutter)
  {
    ArgumentNullException.ThrowIfNull(timeline);
    this.scene = scene;
    render = renderHash;
    this.size = size;
    this.samplesPerPixel = samplesPerPixel;
    this.seed = seed;
    this.timeline = timeline;
    this.shutter = shutter;
  }

  /// <summary>The fingerprint of the frames of <paramref name="setup"/> on <paramref name="timeline"/>.</summary>
  public static FrameFingerprint Of(ISceneSource source, PreparedRender setup, IEnumerable<string> modules, AnimationTimeline timeline, double shutter)
  {
    RenderSettings s = setup.Settings;
    // A script's own renderer may read the raw count; the built-in one takes the square grid.
    int spp = setup.Synthesizer == null ? s.EffectiveSamplesPerPixel : s.SamplesPerPixel;
    // Each frame names its own time; what all frames share is that they are frames.
    string id = RenderIdentity.Describe(source, setup, modules, spp, "frames");
    return new FrameFingerprint(source.DisplayName, RenderIdentity.Hash(id), s.Size, spp, s.Seed, timeline, shutter);
  }

  /// <summary>The text stored in frame <paramref name="frame"/> with these pixels.</summary>
  public string Text(int frame, Rgb8Image pixels) =>
    string.Join('\n', Fields(frame).Select(f => $"{f.Key} {f.Value}").Append($"{PixelsKey} {PixelHash(pixels)}"));

  /// <summary>The entries to write into frame <paramref name="frame"/>'s PNG.</summary>
  public IReadOnlyList<KeyValuePair<string, string>> Entries(int frame, Rgb8Image pixels) =>
    [new(Keyword, Text(frame, pixels))];

  /// <summary>
  /// Compares a stored fingerprint with frame <paramref name="frame"/> of this render: <see cref="FrameState.Kept"/>
  /// when every field but the pixel checksum is equal (which <paramref name="pixels"/> then returns), else why not.
  /// </summary>
  public FrameCheck Compare(int frame, string stored, out string pixels)
  {
    pixels = "";
    var found = new Dictionary<string, string>(StringComparer.Ordinal);
    string[] lines = stored.Split('\n');
    if (lines[0] != FormatLine)
      return new FrameCheck(FrameState.OtherRender, "fingerprint format");
    foreach (string line in lines.Skip(1))
    {
      int space = line.IndexOf(' ');
      if (space > 0)
        found.TryAdd(line[..space], line[(space + 1)..]);
    }

    var differ = new List<string>();
    foreach ((string key, string value) in Fields(frame).Skip(1))
      if (!found.TryGetValue(key, out string? theirs) || theirs != value)
        differ.Add(key);
    if (differ.Count > 0)
      return new FrameCheck(FrameState.OtherRender, Describe(differ));
    if (!found.TryGetValue(PixelsKey, out string? sum) || sum.Length == 0)
      return new FrameCheck(FrameState.Corrupt, "the fingerprint has no pixel checksum");
    pixels = sum;
    return FrameCheck.Kept;
  }

  /// <summary>The pixel checksum as stored: <c>sha256:</c> and the hex SHA-256 of the RGB bytes.</summary>
  public static string PixelHash(Rgb8Image pixels) => "sha256:" + RenderIdentity.Hash(pixels.Data);

  IEnumerable<(string Key, string Value)> Fields(int frame)
  {
    yield return ("grcis-frame", "1");
    yield return ("scene", scene);
    yield return ("render", render);
    yield return ("size", size.ToString());
    yield return ("spp", samplesPerPixel.ToString(CultureInfo.InvariantCulture));
    yield return ("seed", seed.ToString(CultureInfo.InvariantCulture));
    yield return ("from", Num(timeline.Start));
    yield return ("to", Num(timeline.End));
    yield return ("fps", Num(timeline.Fps));
    yield return ("shutter", Num(shutter));
    yield return ("frame", frame.ToString(CultureInfo.InvariantCulture));
    yield return ("time", Num(timeline.FrameTime(frame)));
  }

  static string Num(double x) => x.ToString("R", CultureInfo.InvariantCulture);

  /// <summary>The differing fields in a user's words; the settings hash only when no named setting explains it.</summary>
  static string Describe(List<string> keys)
  {
    var words = new List<string>();
    void Add(string word)
    {
      if (!words.Contains(word))
        words.Add(word);
    }
    foreach (string key in keys)
      switch (key)
      {
        case "render":
          break;
        case "from" or "to" or "fps":
          Add("--from/--to/--fps");
          break;
        case "frame" or "time":
          Add("frame number");
          break;
        default:
          Add(key);
          break;
      }
    bool named = keys.Any(k => k is "scene" or "size" or "spp" or "seed");
    if (keys.Contains("render") && !named)
      words.Insert(0, "script or settings");
    return string.Join(", ", words);
  }
}
