using System;
using System.Diagnostics;
using System.Threading;
using Rendering;
using Rendering.Execution;

namespace GrCis.Cli.Jobs;

/// <summary>
/// One still render: GrCis's <see cref="RayTracing"/> with the chosen switches, sampled by
/// <see cref="SimpleImageSynthesizer"/> (one sample, pixel centre) or
/// <see cref="SupersamplingImageSynthesizer"/>, executed in tiles by <see cref="TileRenderer"/>.
/// </summary>
public static class RenderJob
{
  public static ImageSynthesizer CreateSynthesizer(RenderSettings s)
  {
    ImageSynthesizer r = s.SamplesPerPixel <= 1
      ? new SimpleImageSynthesizer()
      : new SupersamplingImageSynthesizer { Supersampling = s.SamplesPerPixel, Jittering = s.Jitter };
    r.Width = s.Size.Width;
    r.Height = s.Size.Height;
    r.Gamma = s.Gamma;
    return r;
  }

  public static RayTracing CreateImageFunction(IRayScene scene, RenderSettings s) => new(scene)
  {
    DoShadows = s.Shadows,
    DoReflections = s.Reflections,
    DoRefractions = s.Refractions,
    Accel = s.Accel,
  };

  public static RenderResult Run(IRayScene scene, RenderSettings settings, Action<RenderProgress>? progress, CancellationToken cancel) =>
    Run(scene, settings, null, null, progress, cancel);

  /// <summary>Renders with a given image function and renderer (a scene script's), or the defaults where null.</summary>
  public static RenderResult Run(IRayScene scene, RenderSettings settings, IImageFunction? imageFunction, ImageSynthesizer? synthesizer,
                                 Action<RenderProgress>? progress, CancellationToken cancel)
  {
    ImageSynthesizer renderer = synthesizer ?? CreateSynthesizer(settings);
    IImageFunction function = imageFunction ?? CreateImageFunction(scene, settings);
    var options = new RenderOptions { Threads = settings.Threads, Seed = settings.Seed };

    var clock = Stopwatch.StartNew();
    var image = TileRenderer.Render(scene, function, renderer, options, progress, cancel);
    clock.Stop();
    long rays = TileRenderer.LastRenderRays;   // summed from per-thread counters, exact for this render
    return new RenderResult(image, renderer.SamplesPerPixel, clock.Elapsed, rays, cancel.IsCancellationRequested);
  }
}
