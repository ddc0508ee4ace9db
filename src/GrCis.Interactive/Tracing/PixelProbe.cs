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
    // A worker of its own, as a render's (a clone for time-dependent scenes, so a motion-blur function cannot move the
    // job's scene); the thread's own prepared scenes, and its context back afterwards.
    using (WorkerContext.Scope worker = WorkerContext.Begin(null, job.Scene, job.ImageFunction, job.Renderer, job.Options))
    {
      IRayScene scene = worker.Context!.Scene!;

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
  }
}
