using System;
using System.Collections.Generic;
using System.Globalization;
using System.Numerics;

namespace Utilities;

/// <summary>
/// GrCis's list parsers ("1, 2, 3" or JSON-like "[1,2,3]"), fractions of pi, and look-ups of lists, ranges
/// and colours in a parsed <c>param</c> string. Numbers are read with the invariant culture.
/// </summary>
public static partial class Util
{
  /// <summary>The segments of <paramref name="value"/> between separators, each trimmed.</summary>
  public static string[] ParseList(string value, char sep = COMMA)
  {
    string[] list = value.Split(sep);
    for (int i = 0; i < list.Length; i++)
      list[i] = list[i].Trim();
    return list;
  }

  /// <summary>The numeric ids (<see cref="IsId"/>) of a string list; null when there is none.</summary>
  public static HashSet<string>? ParseIdList(string? value)
  {
    HashSet<string>? strings = ParseStringList(value);
    if (strings == null)
      return null;
    strings.RemoveWhere(id => !IsId(id));
    return strings.Count > 0 ? strings : null;
  }

  /// <summary>The distinct items of "a, b" or "[a, b]" (null for null or ""), optionally without their quotes (<see cref="ParseString"/>).</summary>
  public static HashSet<string>? ParseStringList(string? value, bool quotes = false)
  {
    if (string.IsNullOrEmpty(value))
      return null;
    string[] list = ParseList(Unbracket(value));
    if (quotes)
      for (int i = 0; i < list.Length; i++)
        list[i] = ParseString(list[i])!;
    return new HashSet<string>(list);
  }

  /// <summary><paramref name="value"/> without one pair of enclosing single or double quotes.</summary>
  public static string? ParseString(string? value)
  {
    if (value == null || value.Length < 2)
      return value;
    char q = value[0];
    return q == value[^1] && (q == '\'' || q == '"') ? value[1..^1] : value;
  }

  /// <summary>Integers of "1, 2, 3" or "[1,2,3]"; an empty item is 0; null for empty input or any other item.</summary>
  public static List<int>? ParseIntList(string? value, char sep = COMMA) => ParseNumbers<int>(value, sep, NumberStyles.Integer);

  /// <summary>As <see cref="ParseIntList"/>, for floats.</summary>
  public static List<float>? ParseFloatList(string? value, char sep = COMMA) => ParseNumbers<float>(value, sep, NumberStyles.Float);

  /// <summary>As <see cref="ParseIntList"/>, for doubles.</summary>
  public static List<double>? ParseDoubleList(string? value, char sep = COMMA) => ParseNumbers<double>(value, sep, NumberStyles.Float);

  static List<T>? ParseNumbers<T>(string? value, char sep, NumberStyles style) where T : INumber<T>
  {
    if (string.IsNullOrEmpty(value))
      return null;
    string[] items = ParseList(Unbracket(value), sep);
    var result = new List<T>(items.Length);
    foreach (string item in items)
    {
      if (T.TryParse(item, style, CultureInfo.InvariantCulture, out T? v))
        result.Add(v);
      else if (item.Length == 0)
        result.Add(T.Zero);
      else
        return null;
    }
    return result;
  }

  /// <summary>The inside of "[...]" (at least one character inside), else the text itself.</summary>
  static string Unbracket(string value) =>
    value.Length > 2 && value[0] == '[' && value[^1] == ']' ? value[1..^1] : value;

  /// <summary>
  /// Reads a number or a fraction "p/q", optionally times pi: a "pi" suffix multiplies the whole ("2pi", "1/3pi"
  /// is pi/3), and numerator or denominator may carry their own ("pi/4", "-3pi/2"). An empty numerator or
  /// denominator counts as 1, a zero denominator as 1. Leaves <paramref name="val"/> unchanged and returns false
  /// when the text is not such a number.
  /// </summary>
  public static bool ParseRational(string sval, ref double val)
  {
    sval = sval.Trim();
    double scale = 1.0;
    if (sval.Length > 2 && sval.Contains('/') && sval.EndsWith("pi", StringComparison.OrdinalIgnoreCase))
    {
      scale = Math.PI;
      sval = sval[..^2];
    }
    int slash = sval.IndexOf('/');
    double numerator, denominator = 1.0;
    if (slash < 0)
    {
      if (!ParseFactor(sval, 0.0, out numerator))
        return false;
    }
    else if (!ParseFactor(sval[..slash], 1.0, out numerator) || !ParseFactor(sval[(slash + 1)..], 1.0, out denominator))
      return false;
    val = scale * numerator / (denominator == 0.0 ? 1.0 : denominator);
    return true;
  }

  /// <summary>A number with an optional "pi" suffix; <paramref name="empty"/> stands for no text at all (0 means: not allowed).</summary>
  static bool ParseFactor(string text, double empty, out double value)
  {
    text = text.Trim();
    double factor = 1.0;
    if (text.EndsWith("pi", StringComparison.OrdinalIgnoreCase))
    {
      factor = Math.PI;
      text = text[..^2].Trim();
      // "pi" alone or "-pi" is one pi, whatever the empty value.
      if (text is "" or "+" or "-")
      {
        value = text == "-" ? -factor : factor;
        return true;
      }
    }
    if (text.Length == 0)
    {
      value = empty;
      return empty != 0.0;
    }
    bool ok = double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out value);
    value *= factor;
    return ok;
  }

  /// <summary>A <see cref="ParseRational"/> value from the map.</summary>
  public static bool TryParseRational(Dictionary<string, string>? rec, string key, ref double val) =>
    TryGet(rec, key, out string? s) && ParseRational(s, ref val);

  /// <summary>
  /// An integer, or a range "min-max" whose middle (integer division) is taken; with one end missing ("5-", "-9")
  /// the given end. Leaves <paramref name="val"/> unchanged and returns false for anything else.
  /// </summary>
  public static bool TryParseIntRange(Dictionary<string, string>? rec, string key, ref int val)
  {
    if (!TryGet(rec, key, out string? s))
      return false;
    int dash = s.IndexOf('-');
    if (dash < 0)
      return TryParseText(s, ref val);
    int lo = 0, hi = 0;
    bool hasLo = TryParseText(s[..dash], ref lo);
    bool hasHi = TryParseText(s[(dash + 1)..], ref hi);
    if (!hasLo && !hasHi)
      return false;
    val = hasLo && hasHi ? (lo + hi) / 2 : hasLo ? lo : hi;
    return true;
  }

  /// <summary>A <see cref="ParseDoubleList"/> list from the map; <paramref name="val"/> unchanged when missing or unreadable.</summary>
  public static bool TryParse(Dictionary<string, string>? rec, string key, ref List<double> val, char sep = COMMA) =>
    TryGetList(rec, key, ref val, s => ParseDoubleList(s, sep));

  /// <summary>A <see cref="ParseFloatList"/> list from the map.</summary>
  public static bool TryParse(Dictionary<string, string>? rec, string key, ref List<float> val, char sep = COMMA) =>
    TryGetList(rec, key, ref val, s => ParseFloatList(s, sep));

  /// <summary>A <see cref="ParseIntList"/> list from the map.</summary>
  public static bool TryParse(Dictionary<string, string>? rec, string key, ref List<int> val, char sep = COMMA) =>
    TryGetList(rec, key, ref val, s => ParseIntList(s, sep));

  static bool TryGetList<T>(Dictionary<string, string>? rec, string key, ref List<T> val, Func<string, List<T>?> parse)
  {
    if (!TryGet(rec, key, out string? s) || parse(s) is not List<T> list)
      return false;
    val = list;
    return true;
  }

  /// <summary>
  /// A colour from the map: three integers are 0–255 components (scaled to [0, 1]), three reals are
  /// unbounded (HDR) components, negatives clamped to 0. Fewer than three items: false.
  /// </summary>
  public static bool TryParse(Dictionary<string, string>? rec, string key, ref float R, ref float G, ref float B, char sep = COMMA)
  {
    if (!TryGet(rec, key, out string? s))
      return false;
    if (ParseIntList(s, sep) is List<int> ints)
    {
      if (ints.Count < 3)
        return false;
      (R, G, B) = (Saturate(ints[0] / 255.0f), Saturate(ints[1] / 255.0f), Saturate(ints[2] / 255.0f));
      return true;
    }
    if (ParseFloatList(s, sep) is not List<float> { Count: >= 3 } floats)
      return false;
    (R, G, B) = (Math.Max(0.0f, floats[0]), Math.Max(0.0f, floats[1]), Math.Max(0.0f, floats[2]));
    return true;
  }

  /// <summary>The value of the first of <paramref name="keys"/> present in the map, or null.</summary>
  public static string? FirstDefined(Dictionary<string, string>? rec, string[] keys) =>
    FirstValue(rec, keys, static (_, v) => v);

  /// <summary>The first non-empty value among <paramref name="keys"/>, or null.</summary>
  public static string? FirstDefinedNonempty(Dictionary<string, string>? rec, string[] keys) =>
    FirstValue(rec, keys, static (_, v) => v.Length > 0 ? v : null);

  /// <summary>The first of <paramref name="keys"/> with a non-empty value, or null.</summary>
  public static string? FirstDefinedKey(Dictionary<string, string>? rec, string[] keys) =>
    FirstValue(rec, keys, static (k, v) => v.Length > 0 ? k : null);

  /// <summary>The leading letters of the first value among <paramref name="keys"/> that starts with a letter, or null.</summary>
  public static string? FirstDefinedLetters(Dictionary<string, string>? rec, string[] keys) =>
    FirstValue(rec, keys, static (_, v) =>
    {
      int n = 0;
      while (n < v.Length && char.IsLetter(v[n]))
        n++;
      return n > 0 ? v[..n] : null;
    });

  /// <summary>The leading digits (<see cref="NumberPrefix"/>) of the first value among <paramref name="keys"/> that starts with one, or null.</summary>
  public static string? FirstDefinedInteger(Dictionary<string, string>? rec, string[] keys) =>
    FirstValue(rec, keys, static (_, v) => NumberPrefix(v) is { Length: > 0 } digits ? digits : null);

  static string? FirstValue(Dictionary<string, string>? rec, string[] keys, Func<string, string, string?> pick)
  {
    if (rec == null)
      return null;
    foreach (string key in keys)
      if (rec.TryGetValue(key, out string? v) && v != null && pick(key, v) is string result)
        return result;
    return null;
  }

  /// <summary>A key with a value written as invariant text.</summary>
  public static KeyValuePair<string, string> Pair<T>(string key, T val) =>
    new(key, Convert.ToString(val, CultureInfo.InvariantCulture) ?? "");

  /// <summary>
  /// Adds the "key=value" items of <paramref name="str"/> (from index <paramref name="start"/>, items split by
  /// <paramref name="separator"/>) to <paramref name="list"/>, keys prefixed by <paramref name="prefix"/>. A bare
  /// key has the value ""; items with an empty value are skipped unless <paramref name="keepEmpty"/>, with an empty key always.
  /// </summary>
  public static void ParseList(List<KeyValuePair<string, string>> list, string prefix, string str, int start, bool keepEmpty = false, char separator = '&')
  {
    while (start < str.Length)
    {
      int end = str.IndexOf(separator, start);
      if (end < 0)
        end = str.Length;
      int eq = str.IndexOf('=', start, end - start);
      if (eq < 0)
        eq = end;
      string value = eq < end ? str[(eq + 1)..end] : "";
      if (eq > start && (keepEmpty || value.Length > 0))
        list.Add(Pair(prefix + str[start..eq], value));
      start = end + 1;
    }
  }

  /// <summary>An (R, G, B) byte triple from three integer texts; missing or unreadable components are 0, others clamped to 0–255.</summary>
  public static Tuple<byte, byte, byte> ColorTuple(string? rs, string? gs, string? bs)
  {
    static byte Component(string? s) =>
      int.TryParse(s, NumberStyles.Integer, CultureInfo.InvariantCulture, out int v) ? (byte)Math.Clamp(v, 0, 255) : (byte)0;
    return Tuple.Create(Component(rs), Component(gs), Component(bs));
  }

  /// <summary>Some member of the set (the first one enumerated), or null for a null or empty set.</summary>
  public static T? GetFirst<T>(HashSet<T>? set) where T : class
  {
    if (set != null)
      foreach (T item in set)
        return item;
    return null;
  }

  /// <summary>How many members of <paramref name="a"/> <paramref name="b"/> contains.</summary>
  public static int IntersectionSize<T>(ICollection<T> a, ICollection<T> b)
  {
    int count = 0;
    foreach (T item in a)
      if (b.Contains(item))
        count++;
    return count;
  }
}
