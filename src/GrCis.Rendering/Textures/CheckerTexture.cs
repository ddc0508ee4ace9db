using System;
using MathSupport;

namespace Rendering;

/// <summary>A checkerboard in texture coordinates: odd cells get <see cref="Color2"/>, even cells keep the surface colour.</summary>
[Serializable]
public class CheckerTexture : ITexture
{
  /// <summary>Cells per texture-coordinate unit in u and v.</summary>
  public double Fu, Fv;

  public double[] Color2;

  public CheckerTexture(double fu, double fv, double[] color2)
  {
    ArgumentNullException.ThrowIfNull(color2);
    Fu = fu;
    Fv = fv;
    Color2 = (double[])color2.Clone();
  }

  public virtual long Apply(Intersection inter)
  {
    long ui = (long)Math.Floor(inter.TextureCoord.X * Fu);
    long vi = (long)Math.Floor(inter.TextureCoord.Y * Fv);
    // GrCis gives the hit its own copy of Color2; a pooled hit's own colour array takes the values instead.
    if (((ui + vi) & 1) != 0 && !inter.TryCopySurfaceColor(Color2))
      inter.SurfaceColor = (double[])Color2.Clone();
    inter.textureApplied = true;
    return ui + (long)RandomStatic.numericRecipes((ulong)vi);
  }
}
