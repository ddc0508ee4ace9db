namespace Rendering.Execution;

/// <summary>A rectangle of pixels [X1, X2) × [Y1, Y2).</summary>
public readonly record struct Tile(int X1, int Y1, int X2, int Y2)
{
  /// <summary>Number of pixels in the tile.</summary>
  public int PixelCount => (X2 - X1) * (Y2 - Y1);
}
