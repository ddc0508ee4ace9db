using System;
using System.IO;
using Rendering;
using Rendering.Execution;

namespace GrCis.Hosting.Tests;

/// <summary>
/// The render plan is the one builder between front ends and the renderer: the same settings give the
/// same execution options and the same kind of function and sampler whichever way a render is put together.
/// </summary>
public sealed class RenderPlanTests : IDisposable
{
  readonly string dir = Directory.CreateTempSubdirectory("grcis-plan-").FullName;

  public void Dispose() => Directory.Delete(dir, recursive: true);

  static readonly RenderSettings Odd = new()
  {
    Width = 40, Height = 30, SamplesPerPixel = 4, Threads = 3, TileSize = 16, Seed = 77,
    Sampler = SamplerKind.Independent, Algorithm = RenderAlgorithm.Path,
  };

  [Fact]
  public void Same_settings_give_equal_options_through_request_job_and_direct_job()
  {
    PreparedRender prepared = new RenderRequest(new BuiltInSceneSource("Two spheres"), Odd).Prepare();
    RenderOptions expected = new() { Threads = 3, TileSize = 16, Seed = 77, Frame = 0, Sampler = SamplerKind.Independent };

    Assert.Equal(expected, prepared.Plan.CreateOptions());
    Assert.Equal(expected, RenderJob.From(prepared).Options);
    Assert.Equal(expected, RenderJob.Create(new BuiltInSceneSource("Two spheres").CreateScene(), Odd).Options);
    Assert.Equal(expected with { Frame = 5 }, prepared.Plan.CreateOptions(frame: 5));
  }

  [Fact]
  public void Options_of_a_part_carry_only_its_tiles()
  {
    PreparedRender prepared = new RenderRequest(new BuiltInSceneSource("Two spheres"), Odd).Prepare();
    Tile[] tiles = [new Tile(0, 0, 16, 16)];
    Assert.Same(tiles, prepared.Plan.CreateOptions(tiles: tiles).Tiles);
    Assert.Null(prepared.Plan.CreateOptions().Tiles);
  }

  [Fact]
  public void Request_and_job_build_the_settings_function_and_sampler()
  {
    PreparedRender prepared = new RenderRequest(new BuiltInSceneSource("Two spheres"), Odd).Prepare();
    RenderJob job = RenderJob.From(prepared);
    Assert.IsType<PathTracing>(job.ImageFunction);
    Assert.IsType<SupersamplingImageSynthesizer>(job.Renderer);
    Assert.Same(prepared.Plan, job.Plan);
  }

  /// <summary>A Five balls script that sets its own renderer (CTX_SYNTHESIZER).</summary>
  ScriptSceneSource ScriptWithOwnSampler(string file)
  {
    string path = Path.Combine(dir, file);
    File.WriteAllText(path, """
      Rendering.Scenes.FiveBalls(scene);
      context[PropertyName.CTX_SYNTHESIZER] = new SimpleImageSynthesizer();
      """);
    return new ScriptSceneSource(path, "", Array.Empty<string>());
  }

  static PreparedRender PrepareRayTracing(ScriptSceneSource source) =>
    new RenderRequest(source, Odd with { Algorithm = RenderAlgorithm.RayTracing }).Prepare();

  /// <summary>Four frames of <paramref name="prepared"/>'s scene, through its plan.</summary>
  static FrameRenderer Frames(PreparedRender prepared) => new(prepared.Scene, prepared.Plan, new AnimationTimeline(0, 1, 4));

  [Fact]
  public void A_scripts_own_sampler_is_what_request_and_job_render_with()
  {
    using ScriptSceneSource source = ScriptWithOwnSampler("Scene.cs");
    PreparedRender prepared = PrepareRayTracing(source);
    Assert.IsType<SimpleImageSynthesizer>(prepared.Plan.CreateSynthesizer());
    Assert.Same(prepared.Synthesizer, RenderJob.From(prepared).Renderer);
  }

  [Fact]
  public void An_animation_frame_gets_the_options_of_a_still_with_the_same_settings()
  {
    PreparedRender prepared = new RenderRequest(new BuiltInSceneSource("Two spheres"), Odd).Prepare();
    FrameRenderer frames = Frames(prepared);

    Assert.Equal(prepared.Plan.CreateOptions(), frames.Parts.CreateOptions(0, Odd.Threads));
    Assert.Equal(prepared.Plan.CreateOptions(frame: 3), frames.Parts.CreateOptions(3, Odd.Threads));
    // Frames rendered side by side, one thread each: only the thread count differs.
    Assert.Equal(prepared.Plan.CreateOptions(frame: 3) with { Threads = 1 }, frames.Parts.CreateOptions(3, 1));
    Assert.Same(prepared.Plan.Settings, frames.Settings);
  }

  [Fact]
  public void An_animation_frame_builds_the_function_and_sampler_a_still_builds()
  {
    PreparedRender prepared = new RenderRequest(new BuiltInSceneSource("Two spheres"), Odd).Prepare();
    FrameRenderer frames = Frames(prepared);
    IImageFunction still = prepared.Plan.CreateImageFunction(), frame = frames.Parts.CreateFunction(null);
    Assert.IsType<PathTracing>(frame);
    Assert.Equal(((RayCasting)still).Accel, ((RayCasting)frame).Accel);
    ImageSynthesizer stillSampler = prepared.Plan.CreateSynthesizer(), frameSampler = frames.Parts.CreateSynthesizer();
    Assert.Equal(stillSampler.GetType(), frameSampler.GetType());
    Assert.Equal((stillSampler.Width, stillSampler.Height, stillSampler.SamplesPerPixel, stillSampler.Gamma),
                 (frameSampler.Width, frameSampler.Height, frameSampler.SamplesPerPixel, frameSampler.Gamma));
  }

  [Fact]
  public void An_animation_frame_renders_with_a_scripts_own_sampler_as_a_still_does()
  {
    using ScriptSceneSource source = ScriptWithOwnSampler("Frames.cs");
    PreparedRender prepared = PrepareRayTracing(source);
    FrameRenderer frames = Frames(prepared);
    Assert.IsType<SimpleImageSynthesizer>(frames.Parts.CreateSynthesizer());
    Assert.False(frames.Sequential);
  }
}
