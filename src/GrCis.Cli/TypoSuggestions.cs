using System;
using System.Collections.Generic;
using System.CommandLine;
using System.CommandLine.Parsing;
using System.Linq;

namespace GrCis.Cli;

/// <summary>
/// "Did you mean …?" for a mistyped command or option (<c>grcis rendr</c>, <c>grcis render --sise 320x240</c>):
/// a word the parser could not place, or an option-like word it took as the scene, within
/// <see cref="MaxDistance"/> edits (insertion, deletion, substitution, transposition) of a command or option name.
/// </summary>
internal static class TypoSuggestions
{
  /// <summary>The largest edit distance suggested.</summary>
  public const int MaxDistance = 2;

  /// <summary>The usage error for the first mistyped word of <paramref name="parse"/> with a close name, or null.</summary>
  public static string? Find(ParseResult parse)
  {
    ArgumentNullException.ThrowIfNull(parse);
    CommandResult commandResult = parse.CommandResult;
    Command command = commandResult.Command;
    string help = command is RootCommand ? "grcis --help" : $"grcis {command.Name} --help";

    // Words taken as an option's value are the user's values, however they look.
    var values = new HashSet<Token>(parse.Tokens.Where(t => t.Type == TokenType.Argument)
      .Where(t => commandResult.Children.OfType<OptionResult>().Any(o => o.Tokens.Contains(t))));
    var unplaced = parse.UnmatchedTokens.ToHashSet(StringComparer.Ordinal);

    foreach (Token token in parse.Tokens)
    {
      if (token.Type != TokenType.Argument || values.Contains(token))
        continue;
      string word = token.Value;
      bool optionLike = word.Length > 1 && word[0] == '-' && word.TrimStart('-').Length > 0 && char.IsLetter(word.TrimStart('-')[0]);
      if (optionLike)
      {
        string? option = Closest(word, OptionNames(commandResult));
        if (option != null)
          return $"unknown option '{word}': did you mean '{option}'? (see '{help}')";
      }
      else if (unplaced.Contains(word) && command.Subcommands.Count > 0)
      {
        string? sub = Closest(word, command.Subcommands.SelectMany(c => c.Aliases.Prepend(c.Name)));
        if (sub != null)
          return $"unknown command '{word}': did you mean '{sub}'? (see '{help}')";
      }
    }
    return null;
  }

  /// <summary>The options the matched command accepts: its own and its ancestors' recursive ones (--help).</summary>
  static IEnumerable<string> OptionNames(CommandResult commandResult)
  {
    bool own = true;
    for (SymbolResult? r = commandResult; r != null; r = r.Parent)
    {
      if (r is not CommandResult c)
        continue;
      foreach (Option o in c.Command.Options.Where(o => own || o.Recursive))
        foreach (string name in o.Aliases.Prepend(o.Name))
          yield return name;
      own = false;
    }
  }

  /// <summary>
  /// The known name nearest <paramref name="word"/> within <see cref="MaxDistance"/> edits (dashes aside, so <c>-sise</c>
  /// finds <c>--size</c>; a third of the name's letters at most, so a short name needs a closer match), or null. One-
  /// and two-letter names (<c>-o</c>) are one edit from many words and are never guessed.
  /// </summary>
  internal static string? Closest(string word, IEnumerable<string> known)
  {
    string typed = word.TrimStart('-').ToLowerInvariant();
    string? best = null;
    int bestDistance = int.MaxValue;
    foreach (string name in known.Distinct(StringComparer.Ordinal))
    {
      if (name == word)
        return null;
      string letters = name.TrimStart('-').ToLowerInvariant();
      if (letters.Length < 3)
        continue;
      int d = Distance(typed, letters);
      int allowed = Math.Min(MaxDistance, Math.Max(1, letters.Length / 3));
      if (d <= allowed && (d < bestDistance || (d == bestDistance && string.CompareOrdinal(name, best) < 0)))
        (best, bestDistance) = (name, d);
    }
    return best;
  }

  /// <summary>Damerau–Levenshtein distance (optimal string alignment): a swap of neighbours is one edit.</summary>
  internal static int Distance(string a, string b)
  {
    var d = new int[a.Length + 1, b.Length + 1];
    for (int i = 0; i <= a.Length; i++)
      d[i, 0] = i;
    for (int j = 0; j <= b.Length; j++)
      d[0, j] = j;
    for (int i = 1; i <= a.Length; i++)
      for (int j = 1; j <= b.Length; j++)
      {
        int cost = a[i - 1] == b[j - 1] ? 0 : 1;
        d[i, j] = Math.Min(Math.Min(d[i - 1, j] + 1, d[i, j - 1] + 1), d[i - 1, j - 1] + cost);
        if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
          d[i, j] = Math.Min(d[i, j], d[i - 2, j - 2] + 1);
      }
    return d[a.Length, b.Length];
  }
}
