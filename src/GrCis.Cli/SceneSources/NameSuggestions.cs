using System;
using System.Collections.Generic;
using System.Linq;

using GrCis.Hosting;

namespace GrCis.Cli.SceneSources;

/// <summary>"Did you mean …?" for a mistyped scene name: edit distance on names without case, spaces or punctuation.</summary>
public static class NameSuggestions
{
  /// <summary>Known names close to <paramref name="input"/>, best first (at most <paramref name="max"/>).</summary>
  public static IReadOnlyList<string> Closest(string input, IEnumerable<string> known, int max = 3)
  {
    string key = Compact(input);
    if (key.Length == 0)
      return Array.Empty<string>();
    string[] words = Words(input);
    return known
      .Select(name => (name, score: AllWordsMatch(words, Words(name)) ? 1 : Score(key, Compact(name))))
      .Where(x => x.score >= 0)
      .OrderBy(x => x.score)
      .ThenBy(x => x.name, StringComparer.Ordinal)
      .Take(max)
      .Select(x => x.name)
      .ToList();
  }

  /// <summary>Edit distance when close enough to be a typo, 0 for a prefix or substring match, -1 when unrelated.</summary>
  static int Score(string key, string candidate)
  {
    if (candidate.Contains(key, StringComparison.Ordinal) || key.Contains(candidate, StringComparison.Ordinal))
      return 0;
    int d = Levenshtein(key, candidate);
    int allowed = Math.Max(2, Math.Min(key.Length, candidate.Length) / 3);
    return d <= allowed ? d : -1;
  }

  /// <summary>True when every word typed starts a word of the name ("sphere plane" → "Sphere on the plane").</summary>
  static bool AllWordsMatch(string[] typed, string[] name) =>
    typed.Length > 0 && typed.All(t => t.Length >= 3 && name.Any(n => n.StartsWith(t, StringComparison.Ordinal)));

  static string[] Words(string s) =>
    new string(s.Select(c => char.IsLetterOrDigit(c) ? char.ToLowerInvariant(c) : ' ').ToArray())
      .Split(' ', StringSplitOptions.RemoveEmptyEntries);

  static string Compact(string s) =>
    new(s.Where(char.IsLetterOrDigit).Select(char.ToLowerInvariant).ToArray());

  static int Levenshtein(string a, string b)
  {
    var prev = new int[b.Length + 1];
    var cur = new int[b.Length + 1];
    for (int j = 0; j <= b.Length; j++)
      prev[j] = j;
    for (int i = 1; i <= a.Length; i++)
    {
      cur[0] = i;
      for (int j = 1; j <= b.Length; j++)
      {
        int cost = a[i - 1] == b[j - 1] ? 0 : 1;
        cur[j] = Math.Min(Math.Min(cur[j - 1] + 1, prev[j] + 1), prev[j - 1] + cost);
      }
      (prev, cur) = (cur, prev);
    }
    return prev[b.Length];
  }
}
