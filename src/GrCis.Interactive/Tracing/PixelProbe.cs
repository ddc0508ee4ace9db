using System;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

using GrCis.Hosting;

namespace GrCis.Interactive;

/// <summary>
/// The demo's pixel click: the pixel's colour, the hash of its centre sample and the tree of rays
/// that sample traced, recorded by an observer attached to the job's own image function for this one
/// sample (<see cref="RenderContext"/>); ordinary renders attach none and carry no recording cost.
/// </summary>
public static class PixelProbe
{
  /// <summary>Probes pixel (x, y) of <paramref name="job"/>; <paramref name="rendered"/> supplies the pixel colour when given.</summary>
  public static ProbeResult Probe(RenderJob job, int x, int y, FloatImage? rendered = null)
  {
    ArgumentNullException.ThrowIfNull(job);
    if ((uint)x >= (uint)job.Width || (uint)y >= (uint)job.Height)
      throw new ArgumentOutOfRangeException(nameof(x), $"Pixel [{x},{y}] is outside the {job.Width}x{job.Height} image.");

    int bands = rendered?.Bands ?? 3;
    IRayScene? savedScene = MT.scene;
    IImageFunction? savedFunction = MT.imageFunction;
    IRenderer? savedRenderer = MT.renderer;
    long savedSeed = MT.seed;
    int savedFrame = MT.frame;
    try
    {
      MT.InitThreadData();
      // A clone for time-dependent scenes, so a motion-blur function cannot move the job's scene.
      IRayScene scene = SceneCloner.ForFrameWorker(job.Scene, job.ImageFunction);
      MT.SetRendering(scene, job.ImageFunction, job.Renderer);
      MT.seed = job.Options.Seed;
      MT.frame = job.Options.Frame;

      double[] pixel;
      if (rendered != null && rendered.Width == job.Width && rendered.Height == job.Height)
        pixel = rendered.GetPixel(x, y);
      else
      {
        pixel = new double[bands];
        job.Renderer.PixelLinear(x, y, pixel);   // a GrCis-style RenderPixel override too
      }

      // One sample through the pixel centre, seeded as the renderer seeds the pixel.
      double[] sample = new double[bands];
      MT.StartPixel(x, y, 1);
      var observer = new ProbeObserver(scene);
      long hash;
      using (new RenderContext { Observer = observer }.Enter())
        hash = job.ImageFunction.GetSample(x + 0.5, y + 0.5, sample);

      return new ProbeResult(x, y, pixel, sample, hash, observer.Root);
    }
    finally
    {
      MT.SetRendering(savedScene, savedFunction, savedRenderer);
      MT.seed = savedSeed;
      MT.frame = savedFrame;
    }
  }
}
