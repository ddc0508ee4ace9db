using System;
using System.Runtime.CompilerServices;

namespace Rendering;

/// <summary>Linear RGB radiance or throughput inside the path tracer's loop (no array per bounce).</summary>
internal readonly struct Rgb
{
  public readonly double R, G, B;

  public Rgb(double r, double g, double b)
  {
    R = r;
    G = g;
    B = b;
  }

  public Rgb(double v) : this(v, v, v) { }

  public static readonly Rgb Zero = new(0.0);
  public static readonly Rgb One = new(1.0);

  /// <summary>The first three bands of a GrCis colour; a one-band colour is grey.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Rgb From(ReadOnlySpan<double> c) => c.Length switch
  {
    0 => Zero,
    1 or 2 => new Rgb(c[0]),
    _ => new Rgb(c[0], c[1], c[2]),
  };

  /// <summary>Writes into a GrCis colour of any number of bands (bands past the third repeat the third).</summary>
  public void CopyTo(double[] color)
  {
    if (color.Length == 1)
    {
      color[0] = (R + G + B) / 3.0;
      return;
    }
    for (int b = 0; b < color.Length; b++)
      color[b] = b == 0 ? R : b == 1 ? G : B;
  }

  public double Max => Math.Max(R, Math.Max(G, B));

  public double Average => (R + G + B) / 3.0;

  public bool IsBlack => R == 0.0 && G == 0.0 && B == 0.0;

  public static Rgb operator +(in Rgb a, in Rgb b) => new(a.R + b.R, a.G + b.G, a.B + b.B);
  public static Rgb operator *(in Rgb a, in Rgb b) => new(a.R * b.R, a.G * b.G, a.B * b.B);
  public static Rgb operator *(in Rgb a, double k) => new(a.R * k, a.G * k, a.B * k);
  public static Rgb operator *(double k, in Rgb a) => new(a.R * k, a.G * k, a.B * k);
}
