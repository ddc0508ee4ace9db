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

  /// <summary>Image position of the current sample (set by <see cref="RayCasting.GetSample"/> and <see cref="RayTracing.GetSample"/>).</summary>
  [ThreadStatic] public static double doubleX, doubleY;

  /// <summary>Index of this rendering thread, 0 to <see cref="threads"/> − 1 (0 outside rendering).</summary>
  [ThreadStatic] public static int threadID;

  /// <summary>Rendering threads of the render in progress (or the last one).</summary>
  public static int threads = 1;

  /// <summary>GrCis's demo globals, kept so scripts and modules that read or set them still compile.</summary>
  public static int imageWidth;

  public static int imageHeight;

  /// <summary>True while one ray is traced for the demo's ray visualiser (GrCis's pixel probe).</summary>
  public static bool singleRayTracing;

  public static bool sceneRendered;

  public static bool renderingInProgress;

  public static bool pointCloudSavingInProgress;

  public static bool pointCloudCheckBox;

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

  /// <summary>Clears the thread's rendering context.</summary>
  public static void ResetRendering() => SetRendering(null, null, null);

  /// <summary>The current pixel's hash of (seed, frame, pixel); each sample's stream is derived from it.</summary>
  [ThreadStatic] static ulong pixelHash;

  /// <summary>
  /// Starts pixel (px, py) at sample 0: reseeds <see cref="rnd"/> from (seed, frame, pixel), independent of
  /// thread and order.
  /// </summary>
  public static void StartPixel(int px, int py, int samples)
  {
    x = px;
    y = py;
    total = samples;
    rank = 0;
    ulong h = RandomStatic.Mix64((ulong)seed ^ 0x5DEECE66DUL);
    h = RandomStatic.Mix64(h ^ (uint)frame);
    pixelHash = h = RandomStatic.Mix64(h ^ ((ulong)(uint)py << 32 | (uint)px));
    rnd.ResetFast(h);
  }

  /// <summary>Marks the start of sample <paramref name="r"/> of the current pixel.</summary>
  public static void StartSample(int r) => rank = r;

  /// <summary>Advances to the next sample of the current pixel.</summary>
  public static void NextSample() => rank++;

  /// <summary>
  /// Starts sample <paramref name="r"/> of the current pixel on a random stream of its own, derived from (pixel, r):
  /// the samples from here on give the same numbers whether or not the pixel's earlier samples were taken in the
  /// same call, so a pixel's samples may be taken in separate passes (progressive rendering). Stream 0 is the
  /// pixel's own (<see cref="StartPixel"/>).
  /// </summary>
  public static void StartStream(int r)
  {
    rank = r;
    rnd.ResetFast(r == 0 ? pixelHash : RandomStatic.Mix64(pixelHash ^ (ulong)(uint)r * 0xD6E8FEB86659FD93UL));
  }

  /// <summary>Makes sure this thread has its generator.</summary>
  public static void InitThreadData() => _ = rnd;
}
