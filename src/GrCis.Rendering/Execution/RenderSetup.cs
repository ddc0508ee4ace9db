using System;
using Rendering.Imaging;

namespace Rendering.Execution;

/// <summary>
/// How a still render is put together from the usual switches, in one place for every front end
/// (the command line, the demo): Whitted <see cref="RayTracing"/> with the shadow, reflection and
/// refraction switches, sampled by <see cref="SimpleImageSynthesizer"/> (one centred sample) or
/// <see cref="SupersamplingImageSynthesizer"/> (n×n, jittered). Same settings ⇒ same objects ⇒ same image.
/// </summary>
public static class RenderSetup
{
  /// <summary>Display gamma used when none is given (GrCis's default).</summary>
  public const double DefaultGamma = RenderDefaults.Gamma;

  /// <summary>One centred sample for <paramref name="samplesPerPixel"/> ≤ 1, else an n×n grid (rounded up to a square).</summary>
  public static ImageSynthesizer CreateSynthesizer(int width, int height, int samplesPerPixel, double jittering, double gamma = DefaultGamma)
  {
    ImageSynthesizer r = samplesPerPixel <= 1
      ? new SimpleImageSynthesizer()
      : new SupersamplingImageSynthesizer { Supersampling = samplesPerPixel, Jittering = jittering };
    r.Width = width;
    r.Height = height;
    r.Gamma = gamma;
    return r;
  }

  /// <summary>
  /// Ray tracing with the three switches. <paramref name="scene"/> may be null: an unbound function
  /// shades <c>MT.scene</c>, so each render worker uses its own clone of an animated scene.
  /// </summary>
  public static RayTracing CreateRayTracing(IRayScene? scene, bool shadows, bool reflections, bool refractions)
  {
    var rt = new RayTracing(scene);
    ApplySwitches(rt, shadows, reflections, refractions);
    return rt;
  }

  /// <summary>Sets the switches on an existing ray tracer (a script's own, for instance).</summary>
  public static void ApplySwitches(RayTracing rt, bool shadows, bool reflections, bool refractions)
  {
    ArgumentNullException.ThrowIfNull(rt);
    rt.DoShadows = shadows;
    rt.DoReflections = reflections;
    rt.DoRefractions = refractions;
  }

  /// <summary>
  /// The 8-bit image shown and saved: <see cref="DisplayEncoding.ForRender"/> (gamma, ≤ 0.001 = linear, and
  /// GrCis's truncation), so a PNG from the demo equals one from <c>grcis render</c> byte for byte.
  /// </summary>
  public static Rgb8Image ToDisplayImage(FloatImage image, double gamma = DefaultGamma) =>
    DisplayEncoding.ForRender(gamma).Encode(image);
}
