using System;

namespace Rendering;

/// <summary>
/// Motion blur through hidden sampling: before each sample it moves the worker's own scene
/// (<see cref="MT.scene"/>, a per-worker clone) to a time inside the shutter interval
/// [FrameTime, FrameTime + Shutter / Fps]. The interval is split into <see cref="MT.total"/>
/// strata and sample rank r takes a random time in stratum r, so time is stratified without
/// the renderer knowing. The random offset comes from <see cref="MT.rnd"/>, which is seeded per
/// pixel, so the image depends on the seed only, never on threads or tile order.
/// </summary>
/// <remarks>
/// The wrapped function must render <see cref="MT.scene"/> (construct it without a scene, e.g.
/// <c>new RayTracing()</c>); one bound to a fixed scene would ignore the worker's clone, which
/// is reported as an error rather than silently rendering without blur.
/// </remarks>
public class MotionBlurImageFunction : IImageFunction
{
  /// <summary>Motion blur around <paramref name="inner"/>; no blur until <see cref="Shutter"/> is set; <see cref="Fps"/> is 25 until set.</summary>
  /// <param name="inner">The image function that renders each sample; it must render <see cref="MT.scene"/> (see the remarks).</param>
  /// <exception cref="ArgumentNullException"><paramref name="inner"/> is null.</exception>
  public MotionBlurImageFunction(IImageFunction inner)
  {
    ArgumentNullException.ThrowIfNull(inner);
    Inner = inner;
  }

  /// <summary>The wrapped image function.</summary>
  public IImageFunction Inner { get; }

  /// <summary>Time of the frame: the shutter opens here.</summary>
  public double FrameTime { get; set; }

  /// <summary>Fraction of a frame interval the shutter stays open (0 = no blur, 1 = the whole frame).</summary>
  public double Shutter { get; set; }

  /// <summary>Frames per second of the animation (the shutter interval is Shutter / Fps seconds).</summary>
  public double Fps { get; set; } = 25.0;

  /// <summary>Image width in pixels: the wrapped function's.</summary>
  public double Width
  {
    get => Inner.Width;
    set => Inner.Width = value;
  }

  /// <summary>Image height in pixels: the wrapped function's.</summary>
  public double Height
  {
    get => Inner.Height;
    set => Inner.Height = value;
  }

  /// <summary>Time of a sample of rank <paramref name="rank"/> out of <paramref name="total"/> with offset <paramref name="u"/> ∈ [0, 1).</summary>
  public double SampleTime(int rank, int total, double u)
  {
    if (total < 1)
      total = 1;
    rank %= total;
    return FrameTime + (rank + u) / total * (Shutter / Fps);
  }

  /// <summary>
  /// With <see cref="Shutter"/> &gt; 0 and a time-dependent worker scene, moves that scene (and <see cref="MT.time"/>) to
  /// the time of this sample (<see cref="SampleTime"/>), else sets <see cref="MT.time"/> to <see cref="FrameTime"/>; then
  /// returns the wrapped function's sample.
  /// </summary>
  /// <param name="x">Horizontal image coordinate in pixels.</param>
  /// <param name="y">Vertical image coordinate in pixels.</param>
  /// <param name="color">Receives the colour.</param>
  /// <exception cref="InvalidOperationException">The wrapped function is bound to another scene than the worker's.</exception>
  public long GetSample(double x, double y, double[] color)
  {
    if (Shutter > 0.0 && MT.scene is ITimeDependent scene)
    {
      if (Inner is RayCasting rc && !ReferenceEquals(rc.Scene, MT.scene))
        throw new InvalidOperationException(
          "Motion blur needs an image function that renders the worker's scene: create it without a scene (e.g. new RayTracing()).");
      double t = SampleTime(MT.rank, MT.total, MT.rnd.UniformNumber());
      MT.time = t;
      scene.Time = t;
    }
    else
      MT.time = FrameTime;
    return Inner.GetSample(x, y, color);
  }
}
