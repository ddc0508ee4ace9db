using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace GrCis.Rendering.Tests.Compatibility;

/// <summary>Reading the API lists in <c>Data/</c> (tab-separated, <c>#</c> comments), shared by the API-surface tests.</summary>
static class ApiLists
{
  static readonly string DataDir = Path.Combine(AppContext.BaseDirectory, "Compatibility", "Data");

  /// <summary>The lines of <paramref name="fileName"/> split at tabs, without blank and comment lines.</summary>
  public static List<string[]> Read(string fileName) =>
    File.ReadAllLines(Path.Combine(DataDir, fileName))
      .Where(l => l.Length > 0 && !l.StartsWith('#'))
      .Select(l => l.Split('\t'))
      .ToList();

  /// <summary>A parameter list split at its top-level commas ("a, Dictionary&lt;int, int&gt;" is two).</summary>
  public static string[] SplitParameters(string text)
  {
    if (text.Trim().Length == 0)
      return Array.Empty<string>();
    var parts = new List<string>();
    int depth = 0, start = 0;
    for (int i = 0; i < text.Length; i++)
    {
      if (text[i] is '<' or '(' or '[') depth++;
      else if (text[i] is '>' or ')' or ']') depth--;
      else if (text[i] == ',' && depth == 0)
      {
        parts.Add(text[start..i].Trim());
        start = i + 1;
      }
    }
    parts.Add(text[start..].Trim());
    return parts.ToArray();
  }

  /// <summary>Whether an exception's member scope covers <paramref name="member"/>: a member with its parameter
  /// list matches exactly, a bare name covers its overloads, a scope ending in a space covers every member starting so.</summary>
  public static bool MemberMatches(string scope, string member) =>
    scope.EndsWith(')') ? member == scope
    : scope.EndsWith(' ') ? member.StartsWith(scope, StringComparison.Ordinal)
    : member == scope || member.StartsWith(scope + "(", StringComparison.Ordinal);

  /// <summary>
  /// The listed members that are missing without a reason, and those that exist although a pending line still names
  /// them (the line must go: the lists only shrink). <paramref name="reasonOf"/> gives the line covering a member
  /// (its scope and reason), or null.
  /// </summary>
  public static (List<string> Missing, List<string> Stale) Gaps<T>(IEnumerable<T> members, Func<T, bool> exists,
                                                                 Func<T, (string Scope, string Reason)?> reasonOf) where T : notnull
  {
    var missing = new List<string>();
    var stale = new List<string>();
    foreach (T m in members)
    {
      (string Scope, string Reason)? why = reasonOf(m);
      bool present = exists(m);
      if (!present && why == null)
        missing.Add(m.ToString()!);
      else if (present && why is { } w && IsPending(w.Reason))
        stale.Add($"{m} (exists now: remove or narrow the pending line '{w.Scope}')");
    }
    return (missing, stale);
  }

  public static bool IsPending(string reason) => reason.StartsWith("pending", StringComparison.Ordinal);
}
