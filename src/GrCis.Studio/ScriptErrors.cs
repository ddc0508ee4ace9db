using System.Collections.Generic;
using System.Globalization;
using System.Text.RegularExpressions;

namespace GrCis.Studio;

/// <summary>The compiler diagnostics in a script error message (<c>path(line,col): error CS0103: …</c>, one per line).</summary>
internal static partial class ScriptErrors
{
  [GeneratedRegex(@"^.*\((?<line>\d+),(?<column>\d+)\): (?<severity>error|warning) (?<id>[A-Z]+\d+): (?<message>.*)$", RegexOptions.Multiline)]
  private static partial Regex Diagnostic();

  public static IReadOnlyList<ScriptError> Parse(string message)
  {
    var list = new List<ScriptError>();
    foreach (Match m in Diagnostic().Matches(message))
      list.Add(new ScriptError(int.Parse(m.Groups["line"].Value, CultureInfo.InvariantCulture), int.Parse(m.Groups["column"].Value, CultureInfo.InvariantCulture),
                               m.Groups["severity"].Value, m.Groups["id"].Value, m.Groups["message"].Value.TrimEnd('\r')));
    return list;
  }
}
