using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Threading;
using Rendering;
using Rendering.Execution;
using GrCis.Hosting;

namespace GrCis.Cli.Jobs;

/// <summary>
/// One still render: GrCis's <see cref="RayTracing"/> with the chosen switches, sampled by
/// <see cref="SimpleImageSynthesizer"/> (one sample, pixel centre) or
/// <see cref="SupersamplingImageSynthesizer"/>, executed in tiles by <see cref="TileRenderer"/>.
/// </summary>
public static class RenderJob
{
  // The construction is shared with the interactive demo (RenderSetup), so both make the same image.
  public static ImageSynthesizer CreateSynthesizer(RenderSettings s) => s.CreateSynthesizer();

  public static RayTracing CreateImageFunction(IRayScene scene, RenderSettings s) => s.CreateImageFunction(scene);

  public static FrameResult Run(IRayScene scene, RenderSettings settings, Action<RenderProgress>? progress, CancellationToken cancel) =>
    Run(scene, settings, null, null, progress, cancel);

  /// <summary>Renders with a given image function and renderer (a scene script's), or the defaults where null.</summary>
  /// <param name="tiles">Only these tiles (one part of a scaled-out still); null = the whole image.</param>
  public static FrameResult Run(IRayScene scene, RenderSettings settings, IImageFunction? imageFunction, ImageSynthesizer? synthesizer,
                                 Action<RenderProgress>? progress, CancellationToken cancel, IReadOnlyList<Tile>? tiles = null)
  {
    ImageSynthesizer renderer = synthesizer ?? CreateSynthesizer(settings);
    IImageFunction function = imageFunction ?? CreateImageFunction(scene, settings);
    var options = new RenderOptions { Threads = settings.Threads, Seed = settings.Seed, Tiles = tiles };

    return FrameRendering.Render(scene, function, renderer, options, progress, cancel);
  }
}
