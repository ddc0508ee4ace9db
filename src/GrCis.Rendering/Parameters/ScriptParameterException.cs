using System;

namespace GrCis.Scripting;

/// <summary>A parameter value in the script's <c>param</c> string has the wrong form.</summary>
public sealed class ScriptParameterException : Exception
{
  /// <summary>Parameter <paramref name="key"/> has the value <paramref name="value"/> instead of <paramref name="expected"/>; the message says all three.</summary>
  /// <param name="key">The parameter's name.</param>
  /// <param name="value">The text it has.</param>
  /// <param name="expected">What was expected, in words (e.g. "a number (e.g. 1.5)").</param>
  public ScriptParameterException(string key, string value, string expected)
    : base($"parameter '{key}' has the value '{value}', expected {expected}")
  {
    Key = key;
    Value = value;
    Expected = expected;
  }

  /// <summary>The parameter's name.</summary>
  public string Key { get; }

  /// <summary>The text the parameter has.</summary>
  public string Value { get; }

  /// <summary>What was expected, in words.</summary>
  public string Expected { get; }
}
