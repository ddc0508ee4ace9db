using System;
using System.Globalization;

namespace GrCis.Cli.Animation;

/// <summary>
/// <c>--shard i/n</c>: this process renders the frames k with k ≡ i (mod n), so n processes (array
/// jobs, pods, GNU parallel slots) started with i = 0 … n−1 render every frame exactly once.
/// </summary>
public readonly record struct ShardSpec(int Index, int Count)
{
  /// <summary>The whole animation (shard 0 of 1).</summary>
  public static readonly ShardSpec All = new(0, 1);

  public bool Includes(int frame) => frame % Count == Index;

  /// <summary>Parses <c>i/n</c>; <paramref name="option"/> names the option in messages (<c>--tiles</c> reuses the syntax).</summary>
  /// <exception cref="UsageException">Not <c>i/n</c> with 0 ≤ i &lt; n.</exception>
  public static ShardSpec Parse(string text, string option = "--shard")
  {
    string s = text.Trim();
    int slash = s.IndexOf('/');
    if (slash <= 0 || slash == s.Length - 1 ||
        !int.TryParse(s.AsSpan(0, slash), NumberStyles.None, CultureInfo.InvariantCulture, out int i) ||
        !int.TryParse(s.AsSpan(slash + 1), NumberStyles.None, CultureInfo.InvariantCulture, out int n))
      throw new UsageException($"invalid {option} '{text}': expected INDEX/COUNT, e.g. 0/4 (index from 0)");
    if (n < 1)
      throw new UsageException($"invalid {option} '{text}': the count must be at least 1");
    if (i >= n)
      throw new UsageException($"invalid {option} '{text}': the index runs from 0 to {n - 1}");
    return new ShardSpec(i, n);
  }

  public override string ToString() => $"{Index}/{Count}";
}
