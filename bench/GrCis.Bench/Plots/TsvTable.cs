using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;

namespace GrCis.Bench.Plots;

/// <summary>
/// A tab-separated table: optional <c># key: value</c> header lines (date, machine, commit …), then a row of
/// column names, then data rows with exactly as many cells. Blank lines are skipped.
/// </summary>
public sealed class TsvTable
{
  public required string File { get; init; }
  public required IReadOnlyDictionary<string, string> Header { get; init; }
  public required IReadOnlyList<string> Columns { get; init; }
  public required IReadOnlyList<TsvRow> Rows { get; init; }

  public static TsvTable Read(string file)
  {
    if (!System.IO.File.Exists(file))
      throw new PlotInputException(file, 0, "no such file");
    var header = new Dictionary<string, string>(StringComparer.OrdinalIgnoreCase);
    string[]? columns = null;
    var rows = new List<TsvRow>();
    string[] lines = System.IO.File.ReadAllLines(file);
    for (int i = 0; i < lines.Length; i++)
    {
      string text = lines[i];
      if (text.Trim().Length == 0)
        continue;
      if (text.StartsWith('#'))
      {
        int colon = text.IndexOf(':');
        if (colon > 1)
          header[text[1..colon].Trim()] = text[(colon + 1)..].Trim();
        continue;
      }
      string[] cells = text.Split('\t');
      if (columns == null)
      {
        columns = cells;
        continue;
      }
      if (cells.Length != columns.Length)
        throw new PlotInputException(file, i + 1, $"{cells.Length} cells, the header row has {columns.Length}");
      rows.Add(new TsvRow(file, i + 1, columns, cells));
    }
    if (columns == null)
      throw new PlotInputException(file, 0, "no header row");
    return new TsvTable { File = file, Header = header, Columns = columns, Rows = rows };
  }

  /// <summary>Fails unless every named column is present.</summary>
  public TsvTable Require(params string[] names)
  {
    foreach (string n in names)
      if (Array.IndexOf((string[])Columns, n) < 0)
        throw new PlotInputException(File, 0, $"no column '{n}' (columns: {string.Join(", ", Columns)})");
    return this;
  }
}

/// <summary>One data row of a <see cref="TsvTable"/>; lookups fail with the file and line.</summary>
public sealed class TsvRow(string file, int line, string[] columns, string[] cells)
{
  public int Line => line;

  public string Text(string column)
  {
    int i = Array.IndexOf(columns, column);
    if (i < 0)
      throw new PlotInputException(file, line, $"no column '{column}'");
    return cells[i];
  }

  /// <summary>The cell as a number; "-" or "–" (not measured) is null.</summary>
  public double? NumberOrNone(string column)
  {
    string s = Text(column).Trim();
    if (s is "-" or "–" or "")
      return null;
    if (!double.TryParse(s, NumberStyles.Float, CultureInfo.InvariantCulture, out double v) || !double.IsFinite(v))
      throw new PlotInputException(file, line, $"column '{column}': '{s}' is not a number");
    return v;
  }

  public double Number(string column) =>
    NumberOrNone(column) ?? throw new PlotInputException(file, line, $"column '{column}': a number is needed, got '{Text(column)}'");

  public PlotInputException Error(string message) => new(file, line, message);
}
