using System;
using System.Collections.Generic;
using System.Globalization;
using Rendering;

namespace Utilities;

/// <summary>
/// Helpers scene scripts rely on: the <c>param</c> string parser, typed look-ups in parameter
/// and context dictionaries (invariant culture), and small colour-array operations.
/// </summary>
public static partial class Util
{
  /// <summary>Default separator of <see cref="ParseKeyValueList"/>.</summary>
  public const char COMMA = KeyValueText.COMMA;

  /// <summary>
  /// Parses <c>"key=value, key2, key3 = value3"</c>: segments split by <paramref name="separator"/>,
  /// key and value trimmed, a bare key gets the value "" (counts as true), later duplicates win,
  /// empty segments and segments with an empty key are skipped. Null or empty input gives an empty map.
  /// </summary>
  public static Dictionary<string, string> ParseKeyValueList(string? str, char separator = COMMA) =>
    KeyValueText.Parse(str, separator);

  /// <summary>GrCis's "yes" test: a positive integer, or text starting with y, t or a (Czech "ano").</summary>
  public static bool positive(string? val) => KeyValueText.IsYes(val);

  // ---- Dictionary<string, string> (parsed 'param') ----------------------------------------
  // Each overload returns false and leaves 'val' unchanged when the map is null, the key is
  // missing or the text does not parse (rules in KeyValueText, which the script host shares).

  public static bool TryParse(Dictionary<string, string>? rec, string key, ref int val) => KeyValueText.TryParse(rec, key, ref val);

  /// <summary>GrCis's name of the integer <see cref="TryParse(Dictionary{string, string}?, string, ref int)"/> until May 2020.</summary>
  public static bool TryParseInt(Dictionary<string, string>? rec, string key, ref int val) => TryParse(rec, key, ref val);

  public static bool TryParse(Dictionary<string, string>? rec, string key, ref long val) => KeyValueText.TryParse(rec, key, ref val);

  public static bool TryParse(Dictionary<string, string>? rec, string key, ref float val) => KeyValueText.TryParse(rec, key, ref val);

  public static bool TryParse(Dictionary<string, string>? rec, string key, ref double val) => KeyValueText.TryParse(rec, key, ref val);

  /// <summary>A bare key (empty value) or a "yes" value (<see cref="positive"/>) is true; "no", "0", "false" are false.</summary>
  public static bool TryParse(Dictionary<string, string>? rec, string key, ref bool val) => KeyValueText.TryParse(rec, key, ref val);

  public static bool TryParse(Dictionary<string, string>? rec, string key, ref string val) => KeyValueText.TryParse(rec, key, ref val);

  /// <summary>True when the key is present and its value is empty or "yes"-like.</summary>
  public static bool TryParseBool(Dictionary<string, string>? rec, string key) => KeyValueText.TryParseBool(rec, key);

  // ---- Dictionary<string, object> (script context) ----------------------------------------
  // Values may be stored as any numeric type or as text; conversions are invariant-culture.

  public static bool TryParse(Dictionary<string, object>? rec, string key, ref int val) => KeyValueText.TryParse(rec, key, ref val);

  public static bool TryParse(Dictionary<string, object>? rec, string key, ref long val) => KeyValueText.TryParse(rec, key, ref val);

  public static bool TryParse(Dictionary<string, object>? rec, string key, ref float val) => KeyValueText.TryParse(rec, key, ref val);

  public static bool TryParse(Dictionary<string, object>? rec, string key, ref double val) => KeyValueText.TryParse(rec, key, ref val);

  public static bool TryParse(Dictionary<string, object>? rec, string key, ref bool val) => KeyValueText.TryParse(rec, key, ref val);

  public static bool TryParse(Dictionary<string, object>? rec, string key, ref string val) => KeyValueText.TryParse(rec, key, ref val);

  /// <summary>True when the key is present and holds true (or "yes"-like text, or a non-zero number).</summary>
  public static bool TryParseBool(Dictionary<string, object>? rec, string key) => KeyValueText.TryParseBool(rec, key);

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

  // ---- Internals (shared with the list parsers) -------------------------------------------

  static bool TryGet(Dictionary<string, string>? rec, string key, out string value)
  {
    if (rec != null && key != null && rec.TryGetValue(key, out string? v) && v != null)
    {
      value = v;
      return true;
    }
    value = "";
    return false;
  }

  static bool TryParseText(string s, ref int val) => KeyValueText.TryParseValue(s, ref val);

  static bool TryParseText(string s, ref long val) => KeyValueText.TryParseValue(s, ref val);

  static bool TryParseText(string s, ref double val) => KeyValueText.TryParseValue(s, ref val);
}
