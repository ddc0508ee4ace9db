using System;
using System.Collections.Generic;
using Rendering.Execution;

namespace Rendering.Parts;

/// <summary>
/// Which tiles part i of n renders: tile (tx, ty) of the row-major 32-pixel grid belongs to part
/// (tx + ty) mod n. The diagonal interleave gives every part tiles in every row band and every column
/// band, so a costly region (a glass object, a dense mesh) is shared about evenly without a cost pass;
/// a cost pass would need its own render and timings that differ between machines.
/// </summary>
public static class PartLayout
{
  /// <summary>Tile side of parts; fixed so that the layout depends only on image size and part count.</summary>
  public const int TileSize = 32;

  /// <summary>Name written in part files, so a future layout is never merged by this rule.</summary>
  public const string Name = "diagonal-tiles-32";

  /// <summary>The tiles of part <paramref name="index"/> of <paramref name="count"/>, in row-major order (rows of tiles top to bottom, each left to right).</summary>
  /// <param name="width">Image width in pixels.</param>
  /// <param name="height">Image height in pixels.</param>
  /// <param name="index">The part, 0 to <paramref name="count"/> − 1.</param>
  /// <param name="count">Number of parts, at least 1.</param>
  /// <exception cref="ArgumentOutOfRangeException"><paramref name="count"/> is below 1 or <paramref name="index"/> out of range.</exception>
  public static List<Tile> Tiles(int width, int height, int index, int count)
  {
    if (count < 1)
      throw new ArgumentOutOfRangeException(nameof(count), count, "Part count must be at least 1.");
    if (index < 0 || index >= count)
      throw new ArgumentOutOfRangeException(nameof(index), index, $"Part index must be in 0..{count - 1}.");
    var tiles = new List<Tile>();
    foreach (Tile t in TileRenderer.MakeTiles(width, height, TileSize))
      if ((t.X1 / TileSize + t.Y1 / TileSize) % count == index)
        tiles.Add(t);
    return tiles;
  }

  /// <summary>Float samples a part holds (3 bands per pixel).</summary>
  public static long SampleCount(IEnumerable<Tile> tiles, int bands)
  {
    long n = 0;
    foreach (Tile t in tiles)
      n += (long)t.PixelCount * bands;
    return n;
  }
}
