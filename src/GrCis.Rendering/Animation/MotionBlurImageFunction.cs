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
  public MotionBlurImageFunction(IImageFunction inner)
  {
    ArgumentNullException.ThrowIfNull(inner);
    Inner = inner;
  }

  public IImageFunction Inner { get; }

  /// <summary>Time of the frame: the shutter opens here.</summary>
  public double FrameTime { get; set; }

  /// <summary>Fraction of a frame interval the shutter stays open (0 = no blur, 1 = the whole frame).</summary>
  public double Shutter { get; set; }

  /// <summary>Frames per second of the animation (the shutter interval is Shutter / Fps seconds).</summary>
  public double Fps { get; set; } = 25.0;

  public double Width
  {
    get => Inner.Width;
    set => Inner.Width = value;
  }

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
