using System;

namespace GrCis.Editing;

/// <summary>How well a completion entry matches the word typed so far, as editors rank them.</summary>
internal static class CompletionRanking
{
  /// <summary>
  /// 0: starts with the typed word in its case; 1: in another case; 2: the typed letters are the name's
  /// word starts (<c>PM</c> for <c>PhongMaterial</c>); 3: contains it; -1: no match. Everything matches an empty word.
  /// </summary>
  public static int Rank(string name, string typed)
  {
    if (typed.Length == 0 || name.StartsWith(typed, StringComparison.Ordinal))
      return 0;
    if (name.StartsWith(typed, StringComparison.OrdinalIgnoreCase))
      return 1;
    if (WordStarts(name, typed))
      return 2;
    return name.Contains(typed, StringComparison.OrdinalIgnoreCase) ? 3 : -1;
  }

  // The typed word splits into pieces that each begin one of the name's words (an upper-case letter or
  // one after '_'), in order: "PM" and "PhMat" for PhongMaterial.
  static bool WordStarts(string name, string typed) => Humps(name, 0, typed, 0);

  static bool Humps(string name, int from, string typed, int t)
  {
    if (t == typed.Length)
      return true;
    for (int i = from; i < name.Length; i++)
    {
      if (!(i == 0 || char.IsUpper(name[i]) || name[i - 1] == '_'))
        continue;
      // Take one or more letters of this word, then go on at a later word.
      for (int k = 0; t + k < typed.Length && i + k < name.Length && char.ToUpperInvariant(name[i + k]) == char.ToUpperInvariant(typed[t + k]); k++)
        if (Humps(name, i + k + 1, typed, t + k + 1))
          return true;
    }
    return false;
  }
}
