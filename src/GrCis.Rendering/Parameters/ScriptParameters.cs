using System;
using System.Collections.Generic;
using Rendering;

namespace GrCis.Scripting;

/// <summary>
/// Strict reading of a script's <c>param</c> string. <see cref="KeyValueText.TryParse(Dictionary{string, string}, string, ref double)"/>
/// quietly keeps the default when a value does not parse; these getters instead throw a
/// <see cref="ScriptParameterException"/> that says which parameter, which value and what was expected.
/// A missing key gives the default. Usable from scripts (<c>new GrCis.Scripting.ScriptParameters(param)</c>)
/// and from hosts that want to check a parameter string up front. It lives in the library, in the namespace
/// scripts name it by, so a scene script's IDE project (which references the library only) knows it too.
/// </summary>
public sealed class ScriptParameters
{
  /// <summary>Parses a script's <c>param</c> string (<see cref="KeyValueText.Parse"/>), e.g. <c>new ScriptParameters(param)</c>.</summary>
  /// <param name="param">The text, e.g. <c>"n=5, shadows, speed=1.5"</c>; null means empty.</param>
  public ScriptParameters(string? param)
  {
    Text = param ?? "";
    Values = KeyValueText.Parse(Text);
  }

  /// <summary>The original parameter text.</summary>
  public string Text { get; }

  /// <summary>The parsed key → value map (bare keys map to "").</summary>
  public Dictionary<string, string> Values { get; }

  /// <summary>True when <paramref name="key"/> is present (with or without a value).</summary>
  public bool Contains(string key) => Values.ContainsKey(key);

  /// <summary>The value of <paramref name="key"/> as a number (invariant culture, e.g. <c>1.5</c>), or <paramref name="defaultValue"/> when the key is missing.</summary>
  /// <exception cref="ScriptParameterException">The key is present but its value is not a number.</exception>
  public double GetDouble(string key, double defaultValue)
  {
    double v = defaultValue;
    return !Values.ContainsKey(key) || KeyValueText.TryParse(Values, key, ref v) ? v : throw Bad(key, "a number (e.g. 1.5)");
  }

  /// <summary>The value of <paramref name="key"/> as a whole number, or <paramref name="defaultValue"/> when the key is missing.</summary>
  /// <exception cref="ScriptParameterException">The key is present but its value is not a whole number in range.</exception>
  public int GetInt(string key, int defaultValue)
  {
    int v = defaultValue;
    return !Values.ContainsKey(key) || KeyValueText.TryParse(Values, key, ref v) ? v : throw Bad(key, "a whole number (e.g. 4)");
  }

  /// <summary>The value of <paramref name="key"/> as a whole number, or <paramref name="defaultValue"/> when the key is missing.</summary>
  /// <exception cref="ScriptParameterException">The key is present but its value is not a whole number in range.</exception>
  public long GetLong(string key, long defaultValue)
  {
    long v = defaultValue;
    return !Values.ContainsKey(key) || KeyValueText.TryParse(Values, key, ref v) ? v : throw Bad(key, "a whole number (e.g. 4)");
  }

  /// <summary>A bare key means true.</summary>
  public bool GetBool(string key, bool defaultValue)
  {
    bool v = defaultValue;
    return !Values.ContainsKey(key) || KeyValueText.TryParse(Values, key, ref v) ? v : throw Bad(key, "yes/no, true/false, 1/0 or the bare key");
  }

  /// <summary>The text of <paramref name="key"/> ("" for a bare key), or <paramref name="defaultValue"/> when the key is missing.</summary>
  public string GetString(string key, string defaultValue) =>
    Values.TryGetValue(key, out string? v) ? v : defaultValue;

  /// <summary>One of <paramref name="allowed"/> (case-insensitive), returned in its listed spelling.</summary>
  public string GetChoice(string key, string defaultValue, params string[] allowed)
  {
    if (!Values.TryGetValue(key, out string? v))
      return defaultValue;
    foreach (string a in allowed)
      if (string.Equals(a, v, StringComparison.OrdinalIgnoreCase))
        return a;
    throw Bad(key, "one of " + string.Join(", ", allowed));
  }

  ScriptParameterException Bad(string key, string expected) => new(key, Values[key], expected);
}
