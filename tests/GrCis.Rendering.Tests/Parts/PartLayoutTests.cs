using System.Collections.Generic;
using System.IO;
using System.Linq;
using Rendering.Execution;
using Rendering.Imaging;
using Rendering.Parts;

namespace Rendering.Tests.Parts;

public class PartLayoutTests
{
  [Theory]
  [InlineData(640, 480, 1)]
  [InlineData(640, 480, 4)]
  [InlineData(100, 70, 3)]
  [InlineData(33, 31, 7)]
  [InlineData(3840, 2160, 16)]
  public void Parts_cover_every_tile_exactly_once(int width, int height, int count)
  {
    var all = TileRenderer.MakeTiles(width, height, PartLayout.TileSize);
    var parts = Enumerable.Range(0, count).SelectMany(i => PartLayout.Tiles(width, height, i, count)).ToList();
    Assert.Equal(all.Count, parts.Count);
    Assert.Equal(all.ToHashSet(), parts.ToHashSet());
  }

  [Fact]
  public void Every_part_has_tiles_in_every_row_and_column_band()
  {
    // 640x480: 20x15 tiles; 4 parts each get a share of every tile row and tile column.
    for (int i = 0; i < 4; i++)
    {
      List<Tile> tiles = PartLayout.Tiles(640, 480, i, 4);
      Assert.Equal(15, tiles.Select(t => t.Y1).Distinct().Count());
      Assert.Equal(20, tiles.Select(t => t.X1).Distinct().Count());
      Assert.InRange(tiles.Count, 300 / 4 - 1, 300 / 4 + 1);
    }
  }

  [Fact]
  public void Part_file_round_trips_its_header_and_places_its_pixels()
  {
    string dir = Directory.CreateTempSubdirectory("grcis-part-").FullName;
    try
    {
      var image = new FloatImage(70, 40);
      for (int i = 0; i < image.Data.Length; i++)
        image.Data[i] = i * 0.001f - 3f;
      var header = new PartHeader
      {
        Width = 70, Height = 40, Index = 1, Count = 2, SamplesPerPixel = 16, Seed = -5, Gamma = 2.2,
        Scene = "Two spheres", SettingsHash = new string('a', 64),
      };
      string path = Path.Combine(dir, "p.grcis-part");
      PartFile.Save(path, header, image);

      (PartHeader read, float[] samples) = PartFile.Load(path);
      Assert.Equal(header, read);
      var placed = new FloatImage(70, 40);
      PartFile.Place(read, samples, placed);
      foreach (Tile t in PartLayout.Tiles(70, 40, 1, 2))
        Assert.Equal(image.GetPixel(t.X2 - 1, t.Y1), placed.GetPixel(t.X2 - 1, t.Y1));
      Tile other = PartLayout.Tiles(70, 40, 0, 2)[0];
      Assert.Equal(new double[3], placed.GetPixel(other.X1, other.Y1));
    }
    finally
    {
      Directory.Delete(dir, true);
    }
  }
}
