using System.Collections.Generic;
using System.Linq;

namespace GrCis.Cli.Animation;

/// <summary>
/// What <c>--resume</c> found in the frame folder, told as one line: how many existing frames are redone
/// and why (<c>redid 3 frames: 2 from another render (different spp), 1 corrupt (f0007.png: …)</c>). Missing
/// frames are simply rendered and not counted as redone.
/// </summary>
public sealed class ResumeReport
{
  /// <summary>Corrupt files named one by one, up to this many: the rest are counted.</summary>
  public const int NamedCorruptFiles = 3;

  readonly List<(string File, FrameCheck Check)> redone = [];

  /// <summary>Frames kept as they are.</summary>
  public int Kept { get; private set; }

  /// <summary>Frames whose file existed but is rendered again.</summary>
  public int Redone => redone.Count;

  /// <summary>Counts frame <paramref name="file"/>'s check.</summary>
  public void Add(string file, FrameCheck check)
  {
    if (check.State == FrameState.Kept)
      Kept++;
    else if (check.State != FrameState.Missing)
      redone.Add((file, check));
  }

  /// <summary>The frames redone and why, after <paramref name="verb"/> ("redid", "redoing"); empty when none.</summary>
  public string Describe(string verb)
  {
    if (redone.Count == 0)
      return "";
    var parts = new List<string>();
    int n = Count(FrameState.OtherRender);
    if (n > 0)
    {
      string[] why = redone.Where(r => r.Check.State == FrameState.OtherRender)
        .SelectMany(r => r.Check.Detail.Split(", ")).Distinct().ToArray();
      parts.Add($"{n} from another render (different {string.Join(", ", why)})");
    }
    n = Count(FrameState.NoFingerprint);
    if (n > 0)
      parts.Add($"{n} without a fingerprint (written by an older grcis or another program)");
    n = Count(FrameState.Corrupt);
    if (n > 0)
    {
      var named = redone.Where(r => r.Check.State == FrameState.Corrupt).Take(NamedCorruptFiles)
        .Select(r => $"{System.IO.Path.GetFileName(r.File)}: {r.Check.Detail}").ToList();
      if (n > named.Count)
        named.Add($"{n - named.Count} more");
      parts.Add($"{n} corrupt ({string.Join("; ", named)})");
    }
    return $"{verb} {Frames(redone.Count)}: {string.Join(", ", parts)}";
  }

  int Count(FrameState state) => redone.Count(r => r.Check.State == state);

  static string Frames(int n) => n == 1 ? "1 frame" : $"{n} frames";
}
