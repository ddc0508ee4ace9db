using System;
using System.Collections.Generic;
using System.Linq;
using System.Runtime.InteropServices;
using System.Threading;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Rendering.Tests.Execution;

public class TileRendererDeterminismTests
{
  const int Width = 48, Height = 36;

  static FloatImage Render(IRayScene scene, int threads, long seed, int spp = 4, double jitter = 1.0, int frame = 0, int tileSize = 8)
  {
    ImageSynthesizer renderer = spp == 1
      ? new SimpleImageSynthesizer()
      : new SupersamplingImageSynthesizer { Supersampling = spp, Jittering = jitter };
    renderer.Width = Width;
    renderer.Height = Height;
    var options = new RenderOptions { Threads = threads, Seed = seed, Frame = frame, TileSize = tileSize };
    return TileRenderer.Render(scene, new RayTracing(scene), renderer, options);
  }

  static bool BitIdentical(FloatImage a, FloatImage b) =>
    a.Width == b.Width && a.Height == b.Height && a.Bands == b.Bands &&
    MemoryMarshal.AsBytes(a.Data.AsSpan()).SequenceEqual(MemoryMarshal.AsBytes(b.Data.AsSpan()));

  static int DistinctValues(FloatImage image) => image.Data.Distinct().Count();

  [Theory]
  [InlineData(false)]
  [InlineData(true)]
  public void Same_seed_gives_bit_identical_image_with_1_2_and_7_threads(bool areaLight)
  {
    IRayScene scene = TestScenes.BallOnGround(areaLight);
    FloatImage one = Render(scene, threads: 1, seed: 42);
    Assert.True(DistinctValues(one) > 100, "the test image should not be flat");

    FloatImage two = Render(scene, threads: 2, seed: 42);
    FloatImage seven = Render(scene, threads: 7, seed: 42);
    Assert.True(BitIdentical(one, two), "1 vs 2 threads");
    Assert.True(BitIdentical(one, seven), "1 vs 7 threads");
  }

  [Fact]
  public void Tile_size_does_not_change_the_image()
  {
    IRayScene scene = TestScenes.BallOnGround(areaLight: true);
    FloatImage small = Render(scene, threads: 3, seed: 5, tileSize: 5);
    FloatImage large = Render(scene, threads: 3, seed: 5, tileSize: 64);
    Assert.True(BitIdentical(small, large));
  }

  [Theory]
  [InlineData(false)]
  [InlineData(true)]
  public void Different_seeds_give_different_images(bool areaLight)
  {
    IRayScene scene = TestScenes.BallOnGround(areaLight);
    FloatImage a = Render(scene, threads: 2, seed: 1);
    FloatImage b = Render(scene, threads: 2, seed: 2);
    Assert.False(BitIdentical(a, b));
  }

  [Fact]
  public void Different_frames_give_different_sample_streams()
  {
    IRayScene scene = TestScenes.BallOnGround(areaLight: true);
    FloatImage a = Render(scene, threads: 2, seed: 1, frame: 0);
    FloatImage b = Render(scene, threads: 2, seed: 1, frame: 1);
    Assert.False(BitIdentical(a, b));
  }

  [Fact]
  public void One_sample_per_pixel_without_random_components_ignores_the_seed()
  {
    // Pixel centre, point light: nothing random is sampled, so the seed cannot matter.
    IRayScene scene = TestScenes.BallOnGround(areaLight: false);
    Assert.True(BitIdentical(Render(scene, 2, seed: 1, spp: 1), Render(scene, 3, seed: 99, spp: 1)));
  }

  [Fact]
  public void Cancellation_keeps_finished_tiles_and_leaves_the_rest_black()
  {
    IRayScene scene = TestScenes.BallOnGround(areaLight: false);
    FloatImage full = Render(scene, threads: 1, seed: 3);

    var renderer = new SupersamplingImageSynthesizer { Supersampling = 4, Jittering = 1.0, Width = Width, Height = Height };
    var options = new RenderOptions { Threads = 1, Seed = 3, TileSize = 8 };
    using var cts = new CancellationTokenSource();
    var finished = new List<Tile>();
    FloatImage partial = TileRenderer.Render(scene, new RayTracing(scene), renderer, options, p =>
    {
      finished.Add(p.LastTile);
      if (p.TilesDone == 3)
        cts.Cancel();
    }, cts.Token);

    Assert.Equal(3, finished.Count);
    List<Tile> all = TileRenderer.MakeTiles(Width, Height, 8);
    Assert.True(all.Count > 3);
    int compared = 0;
    foreach (Tile t in all)
    {
      bool done = finished.Contains(t);
      for (int y = t.Y1; y < t.Y2; y++)
        for (int x = t.X1; x < t.X2; x++)
          for (int b = 0; b < 3; b++)
          {
            float expected = done ? full[x, y, b] : 0f;
            Assert.Equal(expected, partial[x, y, b]);
            compared++;
          }
    }
    Assert.Equal(Width * Height * 3, compared);
  }

  [Fact]
  public void Progress_reports_each_tile_exactly_once_with_increasing_counts()
  {
    IRayScene scene = TestScenes.BallOnGround(areaLight: false);
    var renderer = new SimpleImageSynthesizer { Width = Width, Height = Height };
    var options = new RenderOptions { Threads = 4, TileSize = 8 };
    var events = new List<RenderProgress>();
    TileRenderer.Render(scene, new RayTracing(scene), renderer, options, events.Add);

    List<Tile> tiles = TileRenderer.MakeTiles(Width, Height, 8);
    Assert.Equal(tiles.Count, events.Count);
    Assert.Equal(Enumerable.Range(1, tiles.Count), events.Select(e => e.TilesDone));
    Assert.All(events, e => Assert.Equal(tiles.Count, e.TilesTotal));
    Assert.Equal(tiles.OrderBy(t => (t.Y1, t.X1)), events.Select(e => e.LastTile).OrderBy(t => (t.Y1, t.X1)));
    Assert.Equal(1.0, events[^1].Fraction);
  }

  [Fact]
  public void Tiles_cover_the_image_exactly_once()
  {
    List<Tile> tiles = TileRenderer.MakeTiles(50, 37, 16);
    var seen = new int[50 * 37];
    foreach (Tile t in tiles)
      for (int y = t.Y1; y < t.Y2; y++)
        for (int x = t.X1; x < t.X2; x++)
          seen[y * 50 + x]++;
    Assert.All(seen, c => Assert.Equal(1, c));
  }

  /// <summary>Fails in every pixel from row <see cref="FromRow"/> on, naming it; the first failing tile is slow to fail.</summary>
  sealed class FailingRows : IImageFunction
  {
    public const int FromRow = 16;
    public double Width { get; set; }
    public double Height { get; set; }

    public long GetSample(double x, double y, double[] color)
    {
      int column = (int)x, row = (int)y;
      if (row >= FromRow)
      {
        if (row < FromRow + 8 && column < 8)
          Thread.Sleep(150);
        throw new InvalidOperationException($"broken at ({column}, {row})");
      }
      color[0] = color[1] = color[2] = 0.5;
      return 1;
    }
  }

  [Theory]
  [InlineData(1)]
  [InlineData(2)]
  [InlineData(7)]
  public void A_failing_render_reports_the_first_failing_tile_whatever_the_threads(int threads)
  {
    IRayScene scene = TestScenes.BallOnGround(areaLight: false);
    var renderer = new SimpleImageSynthesizer { Width = Width, Height = Height };
    var options = new RenderOptions { Threads = threads, TileSize = 8 };
    RenderException e = Assert.Throws<RenderException>(() => TileRenderer.Render(scene, new FailingRows(), renderer, options));
    // Tiles are taken in row-major order: the first failing one is the first tile of row 16.
    Assert.Contains($"broken at (0, {FailingRows.FromRow})", e.Message);
  }
}

