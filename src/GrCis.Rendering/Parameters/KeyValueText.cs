using System;
using System.Collections.Generic;
using System.Globalization;

namespace Rendering;

/// <summary>
/// The <c>param</c> string parser and typed look-ups in parameter and context dictionaries (invariant
/// culture) that the script host needs. GrCis's <c>Util.ParseKeyValueList</c> and <c>Util.TryParse</c>
/// (in GrCis.Compatibility) forward here, so scripts and the host read a parameter the same way.
/// </summary>
public static class KeyValueText
{
  /// <summary>Default separator of <see cref="Parse"/>.</summary>
  public const char COMMA = ',';

  /// <summary>
  /// Parses <c>"key=value, key2, key3 = value3"</c>: segments split by <paramref name="separator"/>,
  /// key and value trimmed, a bare key gets the value "" (counts as true), later duplicates win,
  /// empty segments and segments with an empty key are skipped. Null or empty input gives an empty map.
  /// </summary>
  public static Dictionary<string, string> Parse(string? str, char separator = COMMA)
  {
    var result = new Dictionary<string, string>();
    if (string.IsNullOrEmpty(str))
      return result;

    foreach (string segment in str.Split(separator))
    {
      int eq = segment.IndexOf('=');
      string key = (eq < 0 ? segment : segment[..eq]).Trim();
      if (key.Length == 0)
        continue;
      result[key] = eq < 0 ? "" : segment[(eq + 1)..].Trim();
    }
    return result;
  }

  /// <summary>GrCis's "yes" test: a positive integer, or text starting with y, t or a (Czech "ano").</summary>
  public static bool IsYes(string? val)
  {
    if (string.IsNullOrEmpty(val))
      return false;
    if (int.TryParse(val, NumberStyles.Integer, CultureInfo.InvariantCulture, out int i))
      return i > 0;
    char c = char.ToLowerInvariant(val.TrimStart()[0]);
    return c == 'y' || c == 't' || c == 'a';
  }

  // ---- Dictionary<string, string> (parsed 'param') ----------------------------------------
  // Each overload returns false and leaves 'val' unchanged when the map is null, the key is
  // missing or the text does not parse.

  /// <summary>
  /// Reads the text of <paramref name="key"/> in a parsed <c>param</c> map into <paramref name="val"/> as a number of
  /// <paramref name="val"/>'s type (invariant culture, e.g. <c>1.5</c>). False, with <paramref name="val"/> unchanged, when the map
  /// is null, the key is missing or the text does not parse; so <paramref name="val"/> may hold the default beforehand.
  /// </summary>
  /// <param name="rec">The map from <see cref="Parse"/>, or null.</param>
  /// <param name="key">The parameter's name.</param>
  /// <param name="val">Receives the value.</param>
  public static bool TryParse(Dictionary<string, string>? rec, string key, ref int val) =>
    TryGet(rec, key, out string? s) && TryParseValue(s, ref val);

  /// <inheritdoc cref="TryParse(Dictionary{string, string}, string, ref int)"/>
  public static bool TryParse(Dictionary<string, string>? rec, string key, ref long val) =>
    TryGet(rec, key, out string? s) && TryParseValue(s, ref val);

  /// <inheritdoc cref="TryParse(Dictionary{string, string}, string, ref int)"/>
  public static bool TryParse(Dictionary<string, string>? rec, string key, ref float val) =>
    TryGet(rec, key, out string? s) && TryParseValue(s, ref val);

  /// <inheritdoc cref="TryParse(Dictionary{string, string}, string, ref int)"/>
  public static bool TryParse(Dictionary<string, string>? rec, string key, ref double val) =>
    TryGet(rec, key, out string? s) && TryParseValue(s, ref val);

  /// <summary>A bare key (empty value) or a "yes" value (<see cref="IsYes"/>) is true; "no", "0", "false" are false.</summary>
  public static bool TryParse(Dictionary<string, string>? rec, string key, ref bool val) =>
    TryGet(rec, key, out string? s) && TryParseValue(s, ref val);

  /// <summary>The text of <paramref name="key"/> (trimmed; "" for a bare key); false, with <paramref name="val"/> unchanged, when the map is null or the key is missing.</summary>
  /// <param name="rec">The map from <see cref="Parse"/>, or null.</param>
  /// <param name="key">The parameter's name.</param>
  /// <param name="val">Receives the value.</param>
  public static bool TryParse(Dictionary<string, string>? rec, string key, ref string val)
  {
    if (!TryGet(rec, key, out string? s))
      return false;
    val = s;
    return true;
  }

  /// <summary>True when the key is present and its value is empty or "yes"-like.</summary>
  public static bool TryParseBool(Dictionary<string, string>? rec, string key)
  {
    bool b = false;
    return TryParse(rec, key, ref b) && b;
  }

  // ---- Dictionary<string, object> (script context) ----------------------------------------
  // Values may be stored as any numeric type or as text; conversions are invariant-culture.

  /// <summary>
  /// Reads the value of <paramref name="key"/> in a script context into <paramref name="val"/>: an int, text
  /// (invariant culture), a whole double or float in range, or another primitive number that converts without overflow.
  /// False, with <paramref name="val"/> unchanged, when the map is null, the key is missing or null, or the value does not fit.
  /// </summary>
  /// <param name="rec">The context dictionary, or null.</param>
  /// <param name="key">The key (e.g. <see cref="PropertyName.CTX_WIDTH"/>).</param>
  /// <param name="val">Receives the value.</param>
  public static bool TryParse(Dictionary<string, object>? rec, string key, ref int val)
  {
    if (!TryGet(rec, key, out object? o))
      return false;
    switch (o)
    {
      case int i:
        val = i;
        return true;
      case string s:
        return TryParseValue(s, ref val);
      case double or float:
        double d = Convert.ToDouble(o, CultureInfo.InvariantCulture);
        if (d != Math.Floor(d) || d < int.MinValue || d > int.MaxValue)
          return false;
        val = (int)d;
        return true;
      default:
        return TryConvert(o, ref val, static c => Convert.ToInt32(c, CultureInfo.InvariantCulture));
    }
  }

  /// <summary>
  /// Reads the value of <paramref name="key"/> in a script context into <paramref name="val"/>: a long, text
  /// (invariant culture), a whole double or float in range, or another primitive number that converts without overflow.
  /// False, with <paramref name="val"/> unchanged, when the map is null, the key is missing or null, or the value does not fit.
  /// </summary>
  /// <param name="rec">The context dictionary, or null.</param>
  /// <param name="key">The key.</param>
  /// <param name="val">Receives the value.</param>
  public static bool TryParse(Dictionary<string, object>? rec, string key, ref long val)
  {
    if (!TryGet(rec, key, out object? o))
      return false;
    switch (o)
    {
      case long l:
        val = l;
        return true;
      case string s:
        return TryParseValue(s, ref val);
      case double or float:
        double d = Convert.ToDouble(o, CultureInfo.InvariantCulture);
        if (d != Math.Floor(d) || d < long.MinValue || d > long.MaxValue)
          return false;
        val = (long)d;
        return true;
      default:
        return TryConvert(o, ref val, static c => Convert.ToInt64(c, CultureInfo.InvariantCulture));
    }
  }

  /// <summary>
  /// Reads the value of <paramref name="key"/> in a script context into <paramref name="val"/>: text (invariant culture)
  /// or any primitive number but bool and char. False, with <paramref name="val"/> unchanged, when the map is null, the
  /// key is missing or null, or the value does not convert.
  /// </summary>
  /// <param name="rec">The context dictionary, or null.</param>
  /// <param name="key">The key.</param>
  /// <param name="val">Receives the value.</param>
  public static bool TryParse(Dictionary<string, object>? rec, string key, ref float val)
  {
    if (!TryGet(rec, key, out object? o))
      return false;
    return o is string s
      ? TryParseValue(s, ref val)
      : TryConvert(o, ref val, static c => Convert.ToSingle(c, CultureInfo.InvariantCulture));
  }

  /// <inheritdoc cref="TryParse(Dictionary{string, object}, string, ref float)"/>
  public static bool TryParse(Dictionary<string, object>? rec, string key, ref double val)
  {
    if (!TryGet(rec, key, out object? o))
      return false;
    return o is string s
      ? TryParseValue(s, ref val)
      : TryConvert(o, ref val, static c => Convert.ToDouble(c, CultureInfo.InvariantCulture));
  }

  /// <summary>
  /// Reads the value of <paramref name="key"/> in a script context into <paramref name="val"/>: a bool, text
  /// (<see cref="TryParseValue(string, ref bool)"/>), or a primitive number (true when non-zero). False, with
  /// <paramref name="val"/> unchanged, when the map is null, the key is missing or null, or the value is none of these.
  /// </summary>
  /// <param name="rec">The context dictionary, or null.</param>
  /// <param name="key">The key.</param>
  /// <param name="val">Receives the value.</param>
  public static bool TryParse(Dictionary<string, object>? rec, string key, ref bool val)
  {
    if (!TryGet(rec, key, out object? o))
      return false;
    switch (o)
    {
      case bool b:
        val = b;
        return true;
      case string s:
        return TryParseValue(s, ref val);
      case IConvertible c when o.GetType().IsPrimitive:
        val = Convert.ToDouble(c, CultureInfo.InvariantCulture) != 0.0;
        return true;
      default:
        return false;
    }
  }

  /// <summary>
  /// The value of <paramref name="key"/> in a script context as text (a number written in invariant culture); false,
  /// with <paramref name="val"/> unchanged, when the map is null or the key is missing or null.
  /// </summary>
  /// <param name="rec">The context dictionary, or null.</param>
  /// <param name="key">The key.</param>
  /// <param name="val">Receives the value.</param>
  public static bool TryParse(Dictionary<string, object>? rec, string key, ref string val)
  {
    if (!TryGet(rec, key, out object? o))
      return false;
    val = o as string ?? Convert.ToString(o, CultureInfo.InvariantCulture) ?? "";
    return true;
  }

  /// <summary>True when the key is present and holds true (or "yes"-like text, or a non-zero number).</summary>
  public static bool TryParseBool(Dictionary<string, object>? rec, string key)
  {
    bool b = false;
    return TryParse(rec, key, ref b) && b;
  }

  // ---- One value ---------------------------------------------------------------------------
  // Invariant culture; false and 'val' unchanged when the text does not parse.

  /// <summary>Parses <paramref name="s"/> as a number of <paramref name="val"/>'s type (invariant culture); false, with <paramref name="val"/> unchanged, when it does not parse.</summary>
  /// <param name="s">The text.</param>
  /// <param name="val">Receives the value.</param>
  public static bool TryParseValue(string s, ref int val)
  {
    if (!int.TryParse(s, NumberStyles.Integer, CultureInfo.InvariantCulture, out int v))
      return false;
    val = v;
    return true;
  }

  /// <inheritdoc cref="TryParseValue(string, ref int)"/>
  public static bool TryParseValue(string s, ref long val)
  {
    if (!long.TryParse(s, NumberStyles.Integer, CultureInfo.InvariantCulture, out long v))
      return false;
    val = v;
    return true;
  }

  /// <inheritdoc cref="TryParseValue(string, ref int)"/>
  public static bool TryParseValue(string s, ref float val)
  {
    if (!float.TryParse(s, NumberStyles.Float, CultureInfo.InvariantCulture, out float v))
      return false;
    val = v;
    return true;
  }

  /// <inheritdoc cref="TryParseValue(string, ref int)"/>
  public static bool TryParseValue(string s, ref double val)
  {
    if (!double.TryParse(s, NumberStyles.Float, CultureInfo.InvariantCulture, out double v))
      return false;
    val = v;
    return true;
  }

  /// <summary>
  /// Parses <paramref name="s"/> (trimmed) as a switch: empty text, a "yes" value (<see cref="IsYes"/>) or "on" is true;
  /// any other integer, "no", "n", "false", "f", "off" or "ne" (any case) is false. Anything else does not parse: false,
  /// with <paramref name="val"/> unchanged.
  /// </summary>
  /// <param name="s">The text.</param>
  /// <param name="val">Receives the value.</param>
  public static bool TryParseValue(string s, ref bool val)
  {
    s = s.Trim();
    if (s.Length == 0 || IsYes(s) || s.Equals("on", StringComparison.OrdinalIgnoreCase))
    {
      val = true;
      return true;
    }
    if (int.TryParse(s, NumberStyles.Integer, CultureInfo.InvariantCulture, out _) ||
        s.Equals("no", StringComparison.OrdinalIgnoreCase) ||
        s.Equals("n", StringComparison.OrdinalIgnoreCase) ||
        s.Equals("false", StringComparison.OrdinalIgnoreCase) ||
        s.Equals("f", StringComparison.OrdinalIgnoreCase) ||
        s.Equals("off", StringComparison.OrdinalIgnoreCase) ||
        s.Equals("ne", StringComparison.OrdinalIgnoreCase))
    {
      val = false;
      return true;
    }
    return false;
  }

  // ---- Internals -------------------------------------------------------------------------

  static bool TryGet<T>(Dictionary<string, T>? rec, string key, out T value)
  {
    if (rec != null && key != null && rec.TryGetValue(key, out T? v) && v != null)
    {
      value = v;
      return true;
    }
    value = default!;
    return false;
  }

  static bool TryConvert<T>(object o, ref T val, Func<IConvertible, T> convert)
  {
    if (o is not IConvertible c || !o.GetType().IsPrimitive || o is bool or char)
      return false;
    try
    {
      val = convert(c);
      return true;
    }
    catch (OverflowException)
    {
      return false;
    }
  }
}
