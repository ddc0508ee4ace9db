using System.Collections.Generic;
using System.Linq;
using System.Threading.Tasks;
using GrCis.Hosting;

namespace GrCis.Interactive.Tests;

/// <summary>
/// The demo's preview choice (<see cref="DemoController.Progressive"/>): passes of samples for the Monte Carlo algorithms
/// unless told otherwise, tiles for ray tracing; the final image is the same either way.
/// </summary>
public class ProgressiveChoiceTests
{
  static readonly RenderSettings Sixteen = new() { Width = 32, Height = 24, SamplesPerPixel = 16, Seed = 2, Threads = 2 };

  static async Task<(RenderResult Result, int[] Passes)> Render(RenderAlgorithm algorithm, bool? progressive)
  {
    var catalog = new SceneCatalog();
    catalog.AddBuiltIn("Mirror ball", _ => TestScenes.SphereOnPlane(glass: true));
    using var demo = new DemoController(catalog) { Settings = Sixteen, Algorithm = algorithm, Progressive = progressive, Selected = catalog.Entries[0] };
    var passes = new List<int>();
    demo.PreviewReady += (_, e) =>
    {
      if (e.Samples is int spp)
        lock (passes)
          passes.Add(spp);
    };
    RenderResult? result = await demo.RenderAsync();
    Assert.NotNull(result);
    Assert.True(result.Succeeded, result.Error?.Message);
    lock (passes)
      return (result, passes.Distinct().ToArray());
  }

  [Fact]
  public async Task Path_tracing_renders_in_sample_passes_unless_tiles_are_asked_for_and_the_image_is_the_same()
  {
    var automatic = await Render(RenderAlgorithm.Path, null);
    Assert.Equal(new[] { 1, 4, 8 }, automatic.Passes);
    Assert.NotNull(automatic.Result.Statistics.Noise);

    var tiles = await Render(RenderAlgorithm.Path, false);
    Assert.Empty(tiles.Passes);
    Assert.Equal(automatic.Result.Image.Data, tiles.Result.Image.Data);
    Assert.Equal(automatic.Result.Statistics.Rays, tiles.Result.Statistics.Rays);
  }

  [Fact]
  public async Task Ray_tracing_renders_by_tiles_unless_passes_are_asked_for()
  {
    var automatic = await Render(RenderAlgorithm.RayTracing, null);
    Assert.Empty(automatic.Passes);
    var passes = await Render(RenderAlgorithm.RayTracing, true);
    Assert.Equal(new[] { 1, 4, 8 }, passes.Passes);
    Assert.Equal(automatic.Result.Image.Data, passes.Result.Image.Data);
  }
}
