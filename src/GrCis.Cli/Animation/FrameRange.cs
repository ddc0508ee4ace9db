using System.Globalization;

namespace GrCis.Cli.Animation;

/// <summary><c>--frames a-b</c>: frame numbers a to b, both included (a single number is one frame).</summary>
public readonly record struct FrameRange(int First, int Last)
{
  public int Count => Last - First + 1;

  /// <exception cref="UsageException">Not <c>a-b</c> or <c>a</c> with 0 ≤ a ≤ b.</exception>
  public static FrameRange Parse(string text)
  {
    string s = text.Trim();
    int dash = s.IndexOf('-');
    string a = dash < 0 ? s : s[..dash];
    string b = dash < 0 ? s : s[(dash + 1)..];
    if (!int.TryParse(a, NumberStyles.None, CultureInfo.InvariantCulture, out int first) ||
        !int.TryParse(b, NumberStyles.None, CultureInfo.InvariantCulture, out int last))
      throw new UsageException($"invalid --frames '{text}': expected FIRST-LAST, e.g. 0-249 (frame numbers from 0)");
    if (last < first)
      throw new UsageException($"invalid --frames '{text}': the last frame comes before the first");
    return new FrameRange(first, last);
  }

  public override string ToString() => First == Last ? First.ToString(CultureInfo.InvariantCulture) : $"{First}-{Last}";
}
