namespace Rendering.Execution;

/// <summary>A progress report: how many tiles are done, and which one just finished.</summary>
public readonly record struct RenderProgress(int TilesDone, int TilesTotal, Tile LastTile)
{
  /// <summary>The finished fraction, TilesDone / TilesTotal in [0, 1] (1 when there are no tiles).</summary>
  public double Fraction => TilesTotal == 0 ? 1.0 : (double)TilesDone / TilesTotal;
}
