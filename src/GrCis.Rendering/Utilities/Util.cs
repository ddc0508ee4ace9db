using System;
using System.Collections.Generic;
using System.Globalization;

namespace Utilities;

/// <summary>
/// Helpers scene scripts rely on: the <c>param</c> string parser, typed look-ups in parameter
/// and context dictionaries (invariant culture), and small colour-array operations.
/// </summary>
public static partial class Util
{
  /// <summary>Default separator of <see cref="ParseKeyValueList"/>.</summary>
  public const char COMMA = ',';

  /// <summary>
  /// Parses <c>"key=value, key2, key3 = value3"</c>: segments split by <paramref name="separator"/>,
  /// key and value trimmed, a bare key gets the value "" (counts as true), later duplicates win,
  /// empty segments and segments with an empty key are skipped. Null or empty input gives an empty map.
  /// </summary>
  public static Dictionary<string, string> ParseKeyValueList(string? str, char separator = COMMA)
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
  public static bool positive(string? val)
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

  public static bool TryParse(Dictionary<string, string>? rec, string key, ref int val) =>
    TryGet(rec, key, out string? s) && TryParseText(s, ref val);

  /// <summary>GrCis's name of the integer <see cref="TryParse(Dictionary{string, string}?, string, ref int)"/> until May 2020.</summary>
  public static bool TryParseInt(Dictionary<string, string>? rec, string key, ref int val) => TryParse(rec, key, ref val);

  public static bool TryParse(Dictionary<string, string>? rec, string key, ref long val) =>
    TryGet(rec, key, out string? s) && TryParseText(s, ref val);

  public static bool TryParse(Dictionary<string, string>? rec, string key, ref float val) =>
    TryGet(rec, key, out string? s) && TryParseText(s, ref val);

  public static bool TryParse(Dictionary<string, string>? rec, string key, ref double val) =>
    TryGet(rec, key, out string? s) && TryParseText(s, ref val);

  /// <summary>A bare key (empty value) or a "yes" value (<see cref="positive"/>) is true; "no", "0", "false" are false.</summary>
  public static bool TryParse(Dictionary<string, string>? rec, string key, ref bool val) =>
    TryGet(rec, key, out string? s) && TryParseText(s, ref val);

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
        return TryParseText(s, ref val);
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
        return TryParseText(s, ref val);
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

  public static bool TryParse(Dictionary<string, object>? rec, string key, ref float val)
  {
    if (!TryGet(rec, key, out object? o))
      return false;
    return o is string s
      ? TryParseText(s, ref val)
      : TryConvert(o, ref val, static c => Convert.ToSingle(c, CultureInfo.InvariantCulture));
  }

  public static bool TryParse(Dictionary<string, object>? rec, string key, ref double val)
  {
    if (!TryGet(rec, key, out object? o))
      return false;
    return o is string s
      ? TryParseText(s, ref val)
      : TryConvert(o, ref val, static c => Convert.ToDouble(c, CultureInfo.InvariantCulture));
  }

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
        return TryParseText(s, ref val);
      case IConvertible c when o.GetType().IsPrimitive:
        val = Convert.ToDouble(c, CultureInfo.InvariantCulture) != 0.0;
        return true;
      default:
        return false;
    }
  }

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

  // ---- Colours ---------------------------------------------------------------------------

  /// <summary>A copy of <paramref name="src"/>, optionally multiplied by <paramref name="coeff"/> (null stays null).</summary>
  public static double[]? ColorClone(double[]? src, double coeff = 1.0)
  {
    if (src == null)
      return null;
    var result = new double[src.Length];
    ColorCopy(src, coeff, result);
    return result;
  }

  /// <summary>dst := src over the common bands; extra bands of dst are cleared.</summary>
  public static void ColorCopy(double[] src, double[] dst)
  {
    int n = Math.Min(src.Length, dst.Length);
    Array.Copy(src, dst, n);
    if (n < dst.Length)
      Array.Clear(dst, n, dst.Length - n);
  }

  /// <summary>dst := mul * src over the common bands; extra bands of dst are cleared.</summary>
  public static void ColorCopy(double[] src, double mul, double[] dst)
  {
    int n = Math.Min(src.Length, dst.Length);
    for (int i = 0; i < n; i++)
      dst[i] = mul * src[i];
    if (n < dst.Length)
      Array.Clear(dst, n, dst.Length - n);
  }

  /// <summary>dst += v in every band.</summary>
  public static void ColorAdd(double v, double[] dst)
  {
    for (int i = 0; i < dst.Length; i++)
      dst[i] += v;
  }

  /// <summary>dst += src over the common bands.</summary>
  public static void ColorAdd(double[] src, double[] dst)
  {
    int n = Math.Min(src.Length, dst.Length);
    for (int i = 0; i < n; i++)
      dst[i] += src[i];
  }

  /// <summary>dst += mul * src over the common bands.</summary>
  public static void ColorAdd(double[] src, double mul, double[] dst)
  {
    int n = Math.Min(src.Length, dst.Length);
    for (int i = 0; i < n; i++)
      dst[i] += mul * src[i];
  }

  /// <summary>dst += src ⊙ weight (per band) over the common bands.</summary>
  public static void ColorAdd(double[] src, double[] weight, double[] dst)
  {
    int n = Math.Min(Math.Min(src.Length, weight.Length), dst.Length);
    for (int i = 0; i < n; i++)
      dst[i] += weight[i] * src[i];
  }

  /// <summary>dst *= mul in every band.</summary>
  public static void ColorMul(double mul, double[] dst)
  {
    for (int i = 0; i < dst.Length; i++)
      dst[i] *= mul;
  }

  /// <summary>dst *= weight (per band) over the common bands.</summary>
  public static void ColorMul(double[] weight, double[] dst)
  {
    int n = Math.Min(weight.Length, dst.Length);
    for (int i = 0; i < n; i++)
      dst[i] *= weight[i];
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

  static bool TryParseText(string s, ref int val)
  {
    if (!int.TryParse(s, NumberStyles.Integer, CultureInfo.InvariantCulture, out int v))
      return false;
    val = v;
    return true;
  }

  static bool TryParseText(string s, ref long val)
  {
    if (!long.TryParse(s, NumberStyles.Integer, CultureInfo.InvariantCulture, out long v))
      return false;
    val = v;
    return true;
  }

  static bool TryParseText(string s, ref float val)
  {
    if (!float.TryParse(s, NumberStyles.Float, CultureInfo.InvariantCulture, out float v))
      return false;
    val = v;
    return true;
  }

  static bool TryParseText(string s, ref double val)
  {
    if (!double.TryParse(s, NumberStyles.Float, CultureInfo.InvariantCulture, out double v))
      return false;
    val = v;
    return true;
  }

  static bool TryParseText(string s, ref bool val)
  {
    s = s.Trim();
    if (s.Length == 0 || positive(s) || s.Equals("on", StringComparison.OrdinalIgnoreCase))
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
