using System;
using MathSupport;

namespace Rendering;

/// <summary>
/// Thread-static sampling state ("hidden sampling"): the renderer sets the current pixel and the
/// rank of the current sample within it, and any component (area light, lens, motion blur) may
/// stratify its own random dimension by <see cref="rank"/> out of <see cref="total"/>.
/// </summary>
public static class MT
{
  [ThreadStatic] static RandomJames? rndField;

  /// <summary>This thread's generator; reseeded per pixel from (seed, frame, pixel) for reproducible images.</summary>
  public static RandomJames rnd
  {
    get => rndField ??= new RandomJames();
    set => rndField = value;
  }

  /// <summary>Index of the current sample within the current pixel.</summary>
  [ThreadStatic] public static int rank;

  /// <summary>Number of samples in the current pixel.</summary>
  [ThreadStatic] public static int total;

  /// <summary>Current pixel.</summary>
  [ThreadStatic] public static int x, y;

  /// <summary>Current frame number (animation) and the time of the current sample.</summary>
  [ThreadStatic] public static int frame;

  [ThreadStatic] public static double time;

  /// <summary>What this thread is rendering (for components that need it).</summary>
  [ThreadStatic] public static IRayScene? scene;

  [ThreadStatic] public static IImageFunction? imageFunction;

  [ThreadStatic] public static IRenderer? renderer;

  /// <summary>The user's seed; every pixel's random stream is derived from it.</summary>
  [ThreadStatic] public static long seed;

  /// <summary>Sets the thread's rendering context.</summary>
  public static void SetRendering(IRayScene? sc, IImageFunction? imf, IRenderer? rend)
  {
    scene = sc;
    imageFunction = imf;
    renderer = rend;
  }

  /// <summary>Starts pixel (px, py): reseeds <see cref="rnd"/> from (seed, frame, pixel), independent of thread and order.</summary>
  public static void StartPixel(int px, int py, int samples)
  {
    x = px;
    y = py;
    total = samples;
    rank = 0;
    ulong h = RandomStatic.Mix64((ulong)seed ^ 0x5DEECE66DUL);
    h = RandomStatic.Mix64(h ^ (uint)frame);
    h = RandomStatic.Mix64(h ^ ((ulong)(uint)py << 32 | (uint)px));
    rnd.ResetFast(h);
  }

  /// <summary>Marks the start of sample <paramref name="r"/> of the current pixel.</summary>
  public static void StartSample(int r) => rank = r;

  /// <summary>Advances to the next sample of the current pixel.</summary>
  public static void NextSample() => rank++;

  /// <summary>Makes sure this thread has its generator.</summary>
  public static void InitThreadData() => _ = rnd;
}
