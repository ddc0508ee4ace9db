using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace Utilities;

/// <summary>GrCis's helpers for HTML reports and D3.js charts: colours, palettes, marks.</summary>
public static partial class Util
{
  /// <summary>"#RRGGBB" of 0–255 components (rounded, clamped), not quoted.</summary>
  public static string d3HexColor(float r, float g, float b)
  {
    static int Byte(float c) => Math.Clamp((int)Math.Round(c), 0, 255);
    return string.Create(CultureInfo.InvariantCulture, $"#{Byte(r):X2}{Byte(g):X2}{Byte(b):X2}");
  }

  /// <summary>D3.js code of a categorical palette with at least <paramref name="size"/> colours.</summary>
  public static string d3ColorPalette(int size) =>
    size <= 5 ? "scale5()" : size <= 10 ? "d3.scale.category10()" : "d3.scale.category20()";

  /// <summary>CSS class of green (good) or red (bad) text.</summary>
  public static string GreenRedClass(bool green) => green ? "greent" : "redt";

  /// <summary>HTML up arrow for good, down arrow for bad.</summary>
  public static string UpDownArrow(bool green) => green ? "&uarr;" : "&darr;";

  /// <summary>D3.js code of an ordinal scale of <paramref name="size"/> colours from (r1, g1, b1) to (r2, g2, b2), evenly spaced.</summary>
  public static string d3LinearPalette(int size, int r1, int g1, int b1, int r2, int g2, int b2)
  {
    var hex = new StringBuilder("d3.scale.ordinal().range([");
    hex.Append('"').Append(d3HexColor(r1, g1, b1)).Append('"');
    for (int i = 1; i < size; i++)
    {
      float t = i / (float)(size - 1);
      hex.Append(",\"").Append(d3HexColor(r1 + t * (r2 - r1), g1 + t * (g2 - g1), b1 + t * (b2 - b1))).Append('"');
    }
    return hex.Append("])").ToString();
  }

  /// <summary><see cref="d3LinearPalette(int, int, int, int, int, int, int)"/> with the two colours in one array {r1, g1, b1, r2, g2, b2}.</summary>
  public static string d3LinearPalette(int size, int[] colors) =>
    d3LinearPalette(size, colors[0], colors[1], colors[2], colors[3], colors[4], colors[5]);

  /// <summary>D3.js code of an ordinal scale of the given (R, G, B) colours.</summary>
  public static string d3DiscretePalette(ICollection<Tuple<byte, byte, byte>> table)
  {
    var sb = new StringBuilder("d3.scale.ordinal().range([");
    string sep = "";
    foreach (Tuple<byte, byte, byte> c in table)
    {
      sb.Append(sep).Append('"').Append(d3HexColor(c.Item1, c.Item2, c.Item3)).Append('"');
      sep = ",";
    }
    return sb.Append("])").ToString();
  }

  /// <summary>The number rounded to an integer, in bold when it is positive (above 0.001).</summary>
  public static string CompactFloatHTML(double a)
  {
    string n = a.ToString("f0", CultureInfo.InvariantCulture);
    return a > 1.0e-3 ? "<b>" + n + "</b>" : n;
  }
}
