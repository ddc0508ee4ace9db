using System;

namespace GrCis.Scripting;

/// <summary>A parameter value in the script's <c>param</c> string has the wrong form.</summary>
public sealed class ScriptParameterException : Exception
{
  public ScriptParameterException(string key, string value, string expected)
    : base($"parameter '{key}' has the value '{value}', expected {expected}")
  {
    Key = key;
    Value = value;
    Expected = expected;
  }

  public string Key { get; }

  public string Value { get; }

  public string Expected { get; }
}
