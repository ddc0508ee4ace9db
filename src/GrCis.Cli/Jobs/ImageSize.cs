using System;
using System.Globalization;
using Rendering.Imaging;

namespace GrCis.Cli.Jobs;

/// <summary>Image size given as <c>WxH</c> on the command line.</summary>
public readonly record struct ImageSize(int Width, int Height)
{
  public static readonly ImageSize Default = new(Rendering.Execution.RenderDefaults.Width, Rendering.Execution.RenderDefaults.Height);

  /// <exception cref="UsageException">Not two positive integers separated by 'x', or too large.</exception>
  public static ImageSize Parse(string text)
  {
    string s = text.Trim();
    int x = s.IndexOfAny(['x', 'X', '×']);
    if (x <= 0 || x == s.Length - 1 ||
        !int.TryParse(s.AsSpan(0, x), NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out int w) ||
        !int.TryParse(s.AsSpan(x + 1), NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out int h))
      throw new UsageException($"invalid --size '{text}': expected WIDTHxHEIGHT, e.g. 640x480");
    if (w <= 0 || h <= 0)
      throw new UsageException($"invalid --size '{text}': width and height must be positive");
    if ((long)w * h > Rgb8Image.MaxPixels)
      throw new UsageException($"invalid --size '{text}': at most {Rgb8Image.MaxPixels} pixels");
    return new ImageSize(w, h);
  }

  public override string ToString() => $"{Width}x{Height}";
}
