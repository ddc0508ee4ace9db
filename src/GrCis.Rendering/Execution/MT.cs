using System;
using MathSupport;
using Rendering.Execution;

namespace Rendering;

/// <summary>
/// GrCis's per-thread sampling state ("hidden sampling"): the renderer sets the current pixel and the
/// rank of the current sample within it, and any component (area light, lens, motion blur) may
/// stratify its own random dimension by <see cref="rank"/> out of <see cref="total"/>. Kept for scripts
/// and students' code, as a facade: the per-thread values are properties over the calling thread's
/// <see cref="WorkerContext"/> (the pixel and sample are its <see cref="Sampler"/>'s); GrCis's code only
/// ever read and assigned them (no <c>ref MT.x</c> in its history), which properties allow.
/// </summary>
public static class MT
{
  /// <summary>This thread's generator; reseeded per pixel from (seed, frame, pixel) for reproducible images.</summary>
  public static RandomJames rnd
  {
    get
    {
      WorkerContext c = WorkerContext.Current;
      return c.Rnd ??= new RandomJames();
    }
    set => WorkerContext.Current.Rnd = value;
  }

  /// <summary>Index of the current sample within the current pixel.</summary>
  public static int rank
  {
    get => WorkerContext.Current.Sampler.Index;
    set => WorkerContext.Current.Sampler.Index = value;
  }

  /// <summary>Number of samples in the current pixel.</summary>
  public static int total
  {
    get => WorkerContext.Current.Sampler.Count;
    set => WorkerContext.Current.Sampler.Count = value;
  }

  /// <summary>Current pixel.</summary>
  public static int x
  {
    get => WorkerContext.Current.Sampler.X;
    set => WorkerContext.Current.Sampler.X = value;
  }

  /// <summary>Row of the current pixel (0 at the top); see <see cref="x"/>.</summary>
  public static int y
  {
    get => WorkerContext.Current.Sampler.Y;
    set => WorkerContext.Current.Sampler.Y = value;
  }

  /// <summary>Image position of the current sample (set by <see cref="RayCasting.GetSample"/> and <see cref="RayTracing.GetSample"/>).</summary>
  public static double doubleX
  {
    get => WorkerContext.Current.DoubleX;
    set => WorkerContext.Current.DoubleX = value;
  }

  /// <summary>Vertical image position of the current sample, in pixels; see <see cref="doubleX"/>.</summary>
  public static double doubleY
  {
    get => WorkerContext.Current.DoubleY;
    set => WorkerContext.Current.DoubleY = value;
  }

  /// <summary>Index of this rendering thread, 0 to <see cref="threads"/> − 1 (0 outside rendering).</summary>
  public static int threadID
  {
    get => WorkerContext.Current.ThreadID;
    set => WorkerContext.Current.ThreadID = value;
  }

  /// <summary>Rendering threads of the render in progress (or the last one).</summary>
  public static int threads = 1;

  /// <summary>GrCis's demo globals, kept so scripts and modules that read or set them still compile.</summary>
  public static int imageWidth;

  /// <summary>GrCis's demo global for the image height; the library neither sets nor reads it.</summary>
  public static int imageHeight;

  /// <summary>True while one ray is traced for the demo's ray visualiser (GrCis's pixel probe).</summary>
  public static bool singleRayTracing;

  /// <summary>GrCis's demo flag; the library neither sets nor reads it.</summary>
  public static bool sceneRendered;

  /// <summary>GrCis's demo flag; the library neither sets nor reads it.</summary>
  public static bool renderingInProgress;

  /// <summary>GrCis's demo flag of its point-cloud export; the library neither sets nor reads it.</summary>
  public static bool pointCloudSavingInProgress;

  /// <summary>GrCis's demo flag of its point-cloud export; the library neither sets nor reads it.</summary>
  public static bool pointCloudCheckBox;

  /// <summary>Current frame number (animation) and the time of the current sample.</summary>
  public static int frame
  {
    get => WorkerContext.Current.Sampler.Frame;
    set => WorkerContext.Current.Sampler.Frame = value;
  }

  /// <summary>Time of the current sample in seconds: the frame's time, or within the shutter interval with motion blur (<see cref="MotionBlurImageFunction"/>).</summary>
  public static double time
  {
    get => WorkerContext.Current.Time;
    set => WorkerContext.Current.Time = value;
  }

  /// <summary>What this thread is rendering (for components that need it).</summary>
  public static IRayScene? scene
  {
    get => WorkerScene.Of(WorkerContext.Current);
    set => WorkerScene.Set(WorkerContext.Current, value);
  }

  /// <summary>The image function this thread is rendering with; <see cref="ImageSynthesizer"/> uses it when its own <see cref="ImageSynthesizer.ImageFunction"/> is null.</summary>
  public static IImageFunction? imageFunction
  {
    get => WorkerContext.Current.ImageFunction;
    set => WorkerContext.Current.ImageFunction = value;
  }

  /// <summary>The renderer this thread works for, or null.</summary>
  public static IRenderer? renderer
  {
    get => WorkerContext.Current.Renderer;
    set => WorkerContext.Current.Renderer = value;
  }

  /// <summary>The user's seed; every pixel's random stream is derived from it.</summary>
  public static long seed
  {
    get => WorkerContext.Current.Sampler.Seed;
    set => WorkerContext.Current.Sampler.Seed = value;
  }

  /// <summary>Sets the thread's rendering context.</summary>
  public static void SetRendering(IRayScene? sc, IImageFunction? imf, IRenderer? rend)
  {
    WorkerContext c = WorkerContext.Current;
    c.Scene = sc;
    c.ImageFunction = imf;
    c.Renderer = rend;
  }

  /// <summary>Clears the thread's rendering context.</summary>
  public static void ResetRendering() => SetRendering(null, null, null);

  /// <summary>
  /// Starts pixel (px, py) at sample 0: reseeds <see cref="rnd"/> from (seed, frame, pixel), independent of
  /// thread and order.
  /// </summary>
  public static void StartPixel(int px, int py, int samples)
  {
    WorkerContext c = WorkerContext.Current;
    Sampler s = c.Sampler;
    s.StartPixel(px, py, samples);
    ulong h = RandomStatic.Mix64((ulong)s.Seed ^ 0x5DEECE66DUL);
    h = RandomStatic.Mix64(h ^ (uint)s.Frame);
    c.PixelHash = h = RandomStatic.Mix64(h ^ ((ulong)(uint)py << 32 | (uint)px));
    (c.Rnd ??= new RandomJames()).ResetFast(h);
  }

  /// <summary>Marks the start of sample <paramref name="r"/> of the current pixel.</summary>
  public static void StartSample(int r) => WorkerContext.Current.Sampler.Index = r;

  /// <summary>Advances to the next sample of the current pixel.</summary>
  public static void NextSample() => WorkerContext.Current.Sampler.Index++;

  /// <summary>
  /// Starts sample <paramref name="r"/> of the current pixel on a random stream of its own, derived from (pixel, r):
  /// the samples from here on give the same numbers whether or not the pixel's earlier samples were taken in the
  /// same call, so a pixel's samples may be taken in separate passes (progressive rendering). Stream 0 is the
  /// pixel's own (<see cref="StartPixel"/>).
  /// </summary>
  public static void StartStream(int r)
  {
    WorkerContext c = WorkerContext.Current;
    c.Sampler.Index = r;
    ulong pixelHash = c.PixelHash;
    (c.Rnd ??= new RandomJames()).ResetFast(r == 0 ? pixelHash : RandomStatic.Mix64(pixelHash ^ (ulong)(uint)r * 0xD6E8FEB86659FD93UL));
  }

  /// <summary>Makes sure this thread has its generator.</summary>
  public static void InitThreadData() => _ = rnd;
}
