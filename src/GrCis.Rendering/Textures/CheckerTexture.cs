using System;
using MathSupport;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>A checkerboard in texture coordinates: odd cells get <see cref="Color2"/>, even cells keep the surface colour.</summary>
[Serializable]
public class CheckerTexture : ITexture
{
  /// <summary>Cells per texture-coordinate unit in u and v.</summary>
  public double Fu, Fv;

  /// <summary>Colour of the odd cells, one value per band; it replaces the surface colour there.</summary>
  public double[] Color2;

  /// <summary>A checkerboard, e.g. <c>new CheckerTexture(10.0, 10.0, new double[] { 1.0, 1.0, 1.0 })</c>.</summary>
  /// <param name="fu">Cells per texture-coordinate unit along u (<see cref="Fu"/>).</param>
  /// <param name="fv">Cells per texture-coordinate unit along v (<see cref="Fv"/>).</param>
  /// <param name="color2">Colour of the odd cells (<see cref="Color2"/>; copied).</param>
  /// <exception cref="ArgumentNullException"><paramref name="color2"/> is null.</exception>
  public CheckerTexture(double fu, double fv, double[] color2)
  {
    ArgumentNullException.ThrowIfNull(color2);
    Fu = fu;
    Fv = fv;
    Color2 = (double[])color2.Clone();
  }

  /// <summary>
  /// Cell (⌊u·Fu⌋, ⌊v·Fv⌋) of the hit's <see cref="Intersection.TextureCoord"/>: when the sum of the two indices is odd,
  /// the surface colour becomes a copy of <see cref="Color2"/>. Returns a hash of the cell.
  /// </summary>
  /// <param name="inter">A completed hit.</param>
  public virtual long Apply(Intersection inter)
  {
    // GrCis gives the hit its own copy of Color2; a pooled hit's own colour array takes the values instead.
    if (IsOdd(inter.TextureCoord, out long hash) && !inter.TryCopySurfaceColor(Color2))
      inter.SurfaceColor = (double[])Color2.Clone();
    inter.textureApplied = true;
    return hash;
  }

  /// <summary>True when texture coordinate <paramref name="uv"/> lies in an odd cell; <paramref name="hash"/> is the cell's hash (what <see cref="Apply"/> returns).</summary>
  internal bool IsOdd(in Vector2d uv, out long hash)
  {
    long ui = (long)Math.Floor(uv.X * Fu);
    long vi = (long)Math.Floor(uv.Y * Fv);
    hash = ui + (long)RandomStatic.numericRecipes((ulong)vi);
    return ((ui + vi) & 1) != 0;
  }
}
