using System.Collections.Generic;
using System.Threading.Tasks;
using Rendering;
using Rendering.Imaging;

namespace GrCis.Hosting.Tests;

/// <summary>
/// Which script objects each animation frame may copy (the library's ray tracer and renderers) and which must render
/// every frame themselves, one frame at a time (a class of the script's own); and which renderer a session may run in
/// sample passes (only the library's own n×n grid).
/// </summary>
public class FramePartsTests
{
  sealed class MyTracing : RayTracing
  {
    public int Bounces = 2;
  }

  sealed class MyGrid : SupersamplingImageSynthesizer
  {
  }

  static readonly RenderSettings Small = new() { Width = 24, Height = 16, SamplesPerPixel = 4, TileSize = 8, Threads = 2, Seed = 5 };

  static FrameParts Parts(IImageFunction? function, IRenderer? renderer) =>
    new(Precedence.Resolve(Small, GivenSettings.None, new ScriptChoices { ImageFunction = function, Renderer = renderer }));

  [Fact]
  public void The_library_ray_tracer_and_grid_of_a_script_are_copied_per_frame_with_their_settings()
  {
    var tracer = new RayTracing { MaxLevel = 3, DoShadows = false };
    var grid = new SupersamplingImageSynthesizer { Supersampling = 9, Jittering = 0.25 };
    FrameParts parts = Parts(tracer, grid);

    Assert.False(parts.Sequential);
    Assert.Empty(parts.Notes());
    var function = Assert.IsType<RayTracing>(parts.CreateFunction(null));
    Assert.NotSame(tracer, function);
    Assert.Equal((3, false), (function.MaxLevel, function.DoShadows));
    var synthesizer = Assert.IsType<SupersamplingImageSynthesizer>(parts.CreateSynthesizer());
    Assert.NotSame(grid, synthesizer);
    Assert.Equal((3, 0.25), (synthesizer.SuperXY, synthesizer.Jittering));
  }

  [Fact]
  public void A_scripts_own_classes_render_every_frame_themselves_one_at_a_time()
  {
    var tracer = new MyTracing();
    FrameParts byFunction = Parts(tracer, null);
    Assert.True(byFunction.Sequential);
    Assert.Same(tracer, byFunction.CreateFunction(null));
    Assert.Single(byFunction.Notes());

    var grid = new MyGrid { Supersampling = 4 };
    FrameParts byRenderer = Parts(null, grid);
    Assert.True(byRenderer.Sequential);
    Assert.Same(grid, byRenderer.CreateSynthesizer());
    Assert.IsType<RayTracing>(byRenderer.CreateFunction(null));   // the settings' function, fresh per frame
  }

  [Fact]
  public void Without_script_objects_every_frame_gets_the_settings_function_and_renderer()
  {
    FrameParts parts = Parts(null, null);
    Assert.False(parts.Sequential);
    Assert.NotSame(parts.CreateFunction(null), parts.CreateFunction(null));
    Assert.Equal(4, parts.CreateSynthesizer().SamplesPerPixel);
  }

  [Fact]
  public async Task A_session_asked_for_passes_renders_a_subclassed_grid_by_tiles()
  {
    async Task<List<int>> SamplePasses(ImageSynthesizer renderer)
    {
      RenderJob job = RenderJob.Create(Scenes.Create("Five balls"), Small, renderer: renderer);
      var passes = new List<int>();
      using var session = new RenderSession(job) { Progressive = true, CoarseBlock = 1 };
      session.PreviewReady += (_, e) =>
      {
        if (e.Samples is int spp)
          lock (passes)
            passes.Add(spp);
      };
      FloatImage image = (await session.Start()).Image;
      Assert.NotNull(image);
      lock (passes)
        return passes;
    }

    Assert.NotEmpty(await SamplePasses(new SupersamplingImageSynthesizer { Supersampling = 4 }));
    Assert.Empty(await SamplePasses(new MyGrid { Supersampling = 4 }));
  }
}
