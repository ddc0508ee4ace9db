using System;
using System.Diagnostics;
using System.Threading;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Hosting;

/// <summary>
/// The one frame renderer of every front end (a still, an animation frame, a part of a still, a benchmark
/// case): <see cref="TileRenderer"/> under a fresh <see cref="RenderContext"/>, timed, with its statistics.
/// </summary>
public static class FrameRendering
{
  /// <summary>Renders <paramref name="scene"/>; the tiles of <see cref="RenderOptions.Tiles"/> only, when set.</summary>
  /// <param name="context">Where the rays go (an observer) and the noise estimate; null = a fresh context with a noise estimate.</param>
  /// <exception cref="RenderException">The scene's code failed (the first failing tile in tile order).</exception>
  public static FrameResult Render(IRayScene scene, IImageFunction function, ImageSynthesizer renderer, RenderOptions options,
    Action<RenderProgress>? progress = null, CancellationToken cancel = default, RenderContext? context = null)
  {
    ArgumentNullException.ThrowIfNull(renderer);
    ArgumentNullException.ThrowIfNull(options);
    context ??= new RenderContext { Noise = new NoiseImage(renderer.Width, renderer.Height) };
    int tilesTotal = options.Tiles?.Count ?? TileRenderer.MakeTiles(renderer.Width, renderer.Height, options.TileSize).Count;
    int tilesDone = 0;
    var clock = Stopwatch.StartNew();
    FloatImage image = TileRenderer.Render(scene, function, renderer, options, p =>
    {
      tilesDone = p.TilesDone;
      progress?.Invoke(p);
    }, cancel, context);
    clock.Stop();
    return new FrameResult(image, RenderStatistics.Of(renderer, options, context, clock.Elapsed, tilesDone, tilesTotal, image),
                           cancel.IsCancellationRequested) { Noise = context.Noise };
  }
}
