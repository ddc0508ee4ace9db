using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>A constant background: the scene's BackgroundColor, else its own colour, else a dark default.</summary>
[Serializable]
public class DefaultBackground : IBackground
{
  /// <summary>The colour used when neither the scene nor the background has one: a very dark blue-green (0, 0.02, 0.03).</summary>
  public static readonly double[] DEFAULT_COLOR = { 0.0, 0.02, 0.03 };

  /// <summary>GrCis's name of <see cref="DEFAULT_COLOR"/>, for subclasses.</summary>
  protected static readonly double[] DEFAULT = DEFAULT_COLOR;

  /// <summary>This background's own colour, used when the scene's <see cref="IRayScene.BackgroundColor"/> is null or empty; null or empty means <see cref="DEFAULT_COLOR"/>.</summary>
  public double[]? Color;

  /// <summary>The scene whose BackgroundColor wins over <see cref="Color"/>; subclasses may read it.</summary>
  protected IRayScene? scene;

  /// <summary>The scene whose <see cref="IRayScene.BackgroundColor"/> wins over <see cref="Color"/>, or null.</summary>
  public IRayScene? Scene
  {
    get => scene;
    set => scene = value;
  }

  /// <summary>A fixed colour; null or empty means the default.</summary>
  public DefaultBackground(double[]? color) => Color = color is { Length: > 0 } ? (double[])color.Clone() : null;

  /// <summary>Follows the scene's <see cref="IRayScene.BackgroundColor"/> (read at render time).</summary>
  public DefaultBackground(IRayScene? rtsc = null) => scene = rtsc;

  /// <summary>
  /// The same colour for every direction: the scene's <see cref="IRayScene.BackgroundColor"/>, else <see cref="Color"/>,
  /// else <see cref="DEFAULT_COLOR"/> (bands beyond the colour's last repeat it). Returns 1.
  /// </summary>
  /// <param name="p1">Direction of the ray (not read).</param>
  /// <param name="color">Receives the colour, one value per band.</param>
  public virtual long GetColor(Vector3d p1, double[] color) => Fill(color);

  /// <summary><see cref="GetColor"/> of this class itself (the prepared Whitted kernel calls it directly for exactly this type).</summary>
  internal long Fill(double[] color)
  {
    IRayScene? s = scene;
    double[]? own = s == null ? null : s.BackgroundColor;
    double[]? src = own is { Length: > 0 } sc ? sc
      : Color is { Length: > 0 } ? Color
      : DEFAULT_COLOR;
    for (int i = 0; i < color.Length; i++)
      color[i] = src[Math.Min(i, src.Length - 1)];
    return 1L;
  }
}
