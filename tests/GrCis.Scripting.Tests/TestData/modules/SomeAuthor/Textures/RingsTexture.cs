using System;
using Rendering;

namespace SomeAuthor
{
  /// <summary>Concentric rings around the local z axis: every other ring gets Color2.</summary>
  public class RingsTexture : ITexture
  {
    public double Frequency;
    public double[] Color2;

    public RingsTexture(double frequency, double[] color2)
    {
      Frequency = frequency;
      Color2 = color2;
    }

    public long Apply(Intersection inter)
    {
      double r = Math.Sqrt(inter.CoordLocal.X * inter.CoordLocal.X + inter.CoordLocal.Y * inter.CoordLocal.Y);
      long ring = (long)Math.Floor(r * Frequency);
      if ((ring & 1L) == 1L)
        inter.SurfaceColor = (double[])Color2.Clone();
      return ring;
    }
  }
}
