using System;
using System.Globalization;

namespace GrCis.Hosting;

/// <summary>A setting out of its range: which one, the value and the rule, so each front end words it its own way.</summary>
public sealed class InvalidSettingException : ArgumentException
{
  public InvalidSettingException(Setting setting, object value, string rule)
    : base(string.Create(CultureInfo.InvariantCulture, $"{setting} {value}: {rule}"))
  {
    Setting = setting;
    Value = Convert.ToString(value, CultureInfo.InvariantCulture) ?? "";
    Rule = rule;
  }

  public Setting Setting { get; }

  /// <summary>The value as text (invariant culture).</summary>
  public string Value { get; }

  /// <summary>What the value must be, e.g. "must be at least 1".</summary>
  public string Rule { get; }
}
