using System;

namespace Rendering.Execution;

/// <summary>
/// The default of every render setting, in one place: the command line's options, the script context, the image
/// synthesizers, <c>grcis info</c>, the studio and the demo all read these. They are GrCis's own values.
/// </summary>
public static class RenderDefaults
{
  /// <summary>Image width in pixels (GrCis: 640).</summary>
  public const int Width = 640;

  /// <summary>Image height in pixels (GrCis: 480).</summary>
  public const int Height = 480;

  /// <summary>Samples per pixel: one, at the pixel centre (GrCis's default).</summary>
  public const int SamplesPerPixel = 1;

  /// <summary>Display gamma of 8-bit output (GrCis: 2.2).</summary>
  public const double Gamma = 2.2;

  /// <summary>A gamma at or below this means linear output (GrCis's <c>ApplyGamma</c> rule).</summary>
  public const double LinearGammaLimit = 0.001;

  /// <summary>True when <paramref name="gamma"/> means linear output (≤ <see cref="LinearGammaLimit"/>).</summary>
  public static bool IsLinearGamma(double gamma) => gamma <= LinearGammaLimit;

  /// <summary>Side of the square tiles the image is split into for the worker threads, in pixels.</summary>
  public const int TileSize = 32;

  /// <summary>Start of an animation whose script and scene give none, in seconds (GrCis: 0).</summary>
  public const double AnimationStart = 0.0;

  /// <summary>End of an animation whose script and scene give none, in seconds (GrCis: 10).</summary>
  public const double AnimationEnd = 10.0;

  /// <summary>Frames per second of an animation whose script gives none (GrCis: 25).</summary>
  public const double Fps = 25.0;

  /// <summary>The worker threads a request of <paramref name="requested"/> gives: itself when positive, else one per processor.</summary>
  public static int Threads(int requested) => requested > 0 ? requested : Environment.ProcessorCount;
}
