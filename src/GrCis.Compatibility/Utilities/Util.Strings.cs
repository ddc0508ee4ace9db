using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace Utilities;

/// <summary>GrCis's string helpers: counting, tag substitution, id and address checks, sizes.</summary>
public static partial class Util
{
  /// <summary>Null for an empty string, the interned string otherwise.</summary>
  public static string? EmptyNullIntern(string? s) => string.IsNullOrEmpty(s) ? null : string.Intern(s);

  /// <summary><paramref name="s"/> without the characters a file name cannot hold (and without spaces); "_" when nothing is left.</summary>
  public static string FileNameString(string s)
  {
    var sb = new StringBuilder(s.Length);
    foreach (char ch in s)
      if ("/\\?%*:|\"<> ".IndexOf(ch) < 0)
        sb.Append(ch);
    return sb.Length == 0 ? "_" : sb.ToString();
  }

  /// <summary>How many times <paramref name="ch"/> occurs in <paramref name="s"/> (0 for null).</summary>
  public static int CharsInString(string? s, char ch)
  {
    if (string.IsNullOrEmpty(s))
      return 0;
    int count = 0;
    foreach (char c in s)
      if (c == ch)
        count++;
    return count;
  }

  /// <summary>Number of line ends: "\r\n" and "\n\r" count once, any other CR or LF once each.</summary>
  public static int EolnsInString(string? s)
  {
    if (string.IsNullOrEmpty(s))
      return 0;
    int count = 0;
    for (int i = 0; i < s.Length; i++)
    {
      char c = s[i];
      if (c != '\r' && c != '\n')
        continue;
      count++;
      // The other half of a two-character line end belongs to this one.
      if (i + 1 < s.Length && s[i + 1] == (c == '\r' ? '\n' : '\r'))
        i++;
    }
    return count;
  }

  /// <summary>Replaces every "&lt;%tag&gt;" in <paramref name="str"/> by <paramref name="value"/> (null: removed) and stores the result back.</summary>
  public static string Substitute(ref string str, string tag, string? value) => str = Substitute(str, tag, value);

  /// <summary><paramref name="str"/> with every "&lt;%tag&gt;" replaced by <paramref name="value"/> (null: removed).</summary>
  public static string Substitute(string str, string tag, string? value) =>
    str.Replace("<%" + tag + ">", value ?? "", StringComparison.Ordinal);

  /// <summary>As <see cref="Substitute(ref string, string, string)"/>, the value formatted invariantly from <paramref name="fmt"/>.</summary>
  public static string SubstituteFormat(ref string str, string tag, string fmt, params object[] values) =>
    str = SubstituteFormat(str, tag, fmt, values);

  /// <summary>As <see cref="Substitute(string, string, string)"/>, the value formatted invariantly from <paramref name="fmt"/>.</summary>
  public static string SubstituteFormat(string str, string tag, string fmt, params object[] values)
  {
    string full = "<%" + tag + ">";
    // Format only when the tag is there: the arguments may not fit a format that is never used.
    return str.Contains(full, StringComparison.Ordinal)
      ? str.Replace(full, string.Format(CultureInfo.InvariantCulture, fmt, values), StringComparison.Ordinal)
      : str;
  }

  /// <summary>True for four dot-separated groups of decimal digits ("192.168.0.1"); the group values are not range-checked.</summary>
  public static bool IsIpAddress(string ip)
  {
    string[] groups = ip.Split('.');
    if (groups.Length != 4)
      return false;
    foreach (string g in groups)
    {
      if (g.Length == 0)
        return false;
      foreach (char c in g)
        if (!char.IsAsciiDigit(c))
          return false;
    }
    return true;
  }

  /// <summary>True when <paramref name="id"/> is an integer (a numeric id).</summary>
  public static bool IsId(string? id) =>
    id != null && long.TryParse(id, NumberStyles.Integer, CultureInfo.InvariantCulture, out _);

  /// <summary>The leading decimal digits of <paramref name="val"/> (possibly "").</summary>
  public static string NumberPrefix(string val)
  {
    int i = 0;
    while (i < val.Length && char.IsAsciiDigit(val[i]))
      i++;
    return val[..i];
  }

  /// <summary><paramref name="stIn"/> with accents and other combining marks removed ("Příliš" → "Prilis"); "" for null.</summary>
  public static string RemoveDiacritics(string? stIn)
  {
    if (string.IsNullOrEmpty(stIn))
      return "";
    string decomposed = stIn.Normalize(NormalizationForm.FormD);
    var sb = new StringBuilder(decomposed.Length);
    foreach (char c in decomposed)
      if (CharUnicodeInfo.GetUnicodeCategory(c) != UnicodeCategory.NonSpacingMark)
        sb.Append(c);
    return sb.ToString().Normalize(NormalizationForm.FormC);
  }

  /// <summary>Orders keys: numeric ids first (by value), then "-" last, other text alphabetically in between.</summary>
  public static int KeyComparer(string a, string b)
  {
    bool aNum = long.TryParse(a, NumberStyles.Integer, CultureInfo.InvariantCulture, out long ai);
    bool bNum = long.TryParse(b, NumberStyles.Integer, CultureInfo.InvariantCulture, out long bi);
    if (aNum || bNum)
      return aNum && bNum ? ai.CompareTo(bi) : aNum ? -1 : 1;
    if (a == "-" || b == "-")
      return a == b ? 0 : a == "-" ? 1 : -1;
    return string.Compare(a, b, StringComparison.InvariantCulture);
  }

  /// <summary>
  /// Splits <paramref name="str"/> from index <paramref name="start"/> at each '|'; "\|" stands for a '|' inside a part.
  /// Null when <paramref name="start"/> is past the end.
  /// </summary>
  public static List<string>? BarSplit(string str, int start)
  {
    if (start > str.Length)
      return null;
    var parts = new List<string>();
    var part = new StringBuilder();
    for (int i = start; i < str.Length; i++)
    {
      char c = str[i];
      if (c != '|')
        part.Append(c);
      else if (i > start && str[i - 1] == '\\' && part.Length > 0)
        part[^1] = '|';
      else
      {
        parts.Add(part.ToString());
        part.Clear();
      }
    }
    parts.Add(part.ToString());
    return parts;
  }

  /// <summary>Estimated bytes a string takes (4 for a reference to a null or interned string), as GrCis reckoned it.</summary>
  public static int OccupiedString(string? s)
  {
    if (s == null || string.IsInterned(s) != null)
      return 4;
    // Object header, length and terminator, two bytes per character, rounded up to 4 bytes.
    int bytes = 8 + 4 + 2 + 2 * s.Length;
    return (bytes + 3) & -4;
  }

  /// <summary>Sum of <see cref="OccupiedString"/> over the strings (0 for null).</summary>
  public static int OccupiedStrings(IEnumerable<string?>? ss)
  {
    int total = 0;
    if (ss != null)
      foreach (string? s in ss)
        total += OccupiedString(s);
    return total;
  }

  /// <summary>Adds to <paramref name="result"/>: [0] strings, [1] characters, [2] interned strings, [3] their characters. Ignores nulls and short arrays.</summary>
  public static void StringStat(string? s, long[]? result)
  {
    if (s == null || result == null || result.Length < 4)
      return;
    result[0]++;
    result[1] += s.Length;
    if (string.IsInterned(s) != null)
    {
      result[2]++;
      result[3] += s.Length;
    }
  }

  /// <summary><see cref="StringStat(string, long[])"/> over every string.</summary>
  public static void StringStat(IEnumerable<string?>? ss, long[]? result)
  {
    if (ss == null || result == null || result.Length < 4)
      return;
    foreach (string? s in ss)
      StringStat(s, result);
  }

  /// <summary>A count in binary units: below 8192 as is, else rounded down to K, M, G or T (1024-based).</summary>
  public static string kmg(long n)
  {
    const string units = "KMG";
    if (n < 8192L)
      return n.ToString(CultureInfo.InvariantCulture);
    foreach (char unit in units)
    {
      n >>= 10;
      if (n < 8192L)
        return n.ToString(CultureInfo.InvariantCulture) + unit;
    }
    return (n >> 10).ToString(CultureInfo.InvariantCulture) + "T";
  }

  /// <summary>The strings, each interned (null for null input).</summary>
  public static List<string>? ListStringInterned(IEnumerable<string>? input)
  {
    if (input == null)
      return null;
    var result = new List<string>();
    foreach (string s in input)
      result.Add(string.Intern(s));
    return result;
  }
}
