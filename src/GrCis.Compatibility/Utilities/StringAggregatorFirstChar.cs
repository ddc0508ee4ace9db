using System;

namespace Utilities;

/// <summary>
/// Groups strings by their part before the first <c>separator</c> (GrCis; default '('): "Sphere(3)" and
/// "Sphere(7)" both reduce to "Sphere".
/// </summary>
public sealed class StringAggregatorFirstChar : IAggregator<string>
{
  readonly char separator;

  public StringAggregatorFirstChar(char sep = '(') => separator = sep;

  /// <summary>Compares the reduced keys (culture-sensitive, as <see cref="string.Compare(string, string)"/>).</summary>
  public int Compare(string? x, string? y) => string.Compare(ReduceKey(x!), ReduceKey(y!));

  /// <summary>The part of <paramref name="key"/> before the separator (all of it when there is none); null stays null.</summary>
  public string ReduceKey(string key)
  {
    if (key == null)
      return null!;
    int pos = key.IndexOf(separator, StringComparison.Ordinal);
    return pos >= 0 ? key[..pos] : key;
  }
}
