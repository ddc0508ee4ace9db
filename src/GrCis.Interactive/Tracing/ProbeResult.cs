using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace GrCis.Interactive;

/// <summary>What the demo shows for a clicked pixel.</summary>
public sealed class ProbeResult
{
  internal ProbeResult(int x, int y, double[] pixelColor, double[] sampleColor, long hash, RayNode? rays)
  {
    X = x;
    Y = y;
    PixelColor = pixelColor;
    SampleColor = sampleColor;
    Hash = hash;
    Rays = rays;
  }

  public int X { get; }

  public int Y { get; }

  /// <summary>The pixel's linear colour with all its samples (what the image holds).</summary>
  public double[] PixelColor { get; }

  /// <summary>Colour of the single sample through the pixel centre, the one whose rays are listed.</summary>
  public double[] SampleColor { get; }

  /// <summary>Hash the image function returned for the centre sample.</summary>
  public long Hash { get; }

  /// <summary>Tree of rays of the centre sample; null when the image function reports none (it is not a <see cref="Rendering.RayCasting"/>).</summary>
  public RayNode? Rays { get; }

  /// <summary>All rays, depth first (empty when <see cref="Rays"/> is null).</summary>
  public IEnumerable<RayNode> AllRays => Rays?.Flatten() ?? System.Array.Empty<RayNode>();

  /// <summary>Multi-line text for a read-out panel.</summary>
  public override string ToString()
  {
    var sb = new StringBuilder();
    sb.Append(CultureInfo.InvariantCulture, $"pixel [{X},{Y}] = ({Format(PixelColor)}), centre sample ({Format(SampleColor)}), hash {Hash:X}");
    if (Rays != null)
      Append(sb, Rays, 1);
    return sb.ToString();
  }

  static void Append(StringBuilder sb, RayNode node, int indent)
  {
    sb.AppendLine().Append(' ', 2 * indent).Append(node);
    foreach (RayNode c in node.Children)
      Append(sb, c, indent + 1);
  }

  static string Format(double[] c)
  {
    var parts = new string[c.Length];
    for (int i = 0; i < c.Length; i++)
      parts[i] = c[i].ToString("0.####", CultureInfo.InvariantCulture);
    return string.Join(", ", parts);
  }
}
