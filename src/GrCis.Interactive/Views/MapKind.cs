namespace GrCis.Interactive;

/// <summary>The extra views of a render (GrCis's "Additional views" window).</summary>
public enum MapKind
{
  /// <summary>Distance from the camera to the first hit, averaged over the pixel's primary rays.</summary>
  Depth,

  /// <summary>Angle in degrees between the normal and the direction to the viewer (0 = facing the camera).</summary>
  NormalRelative,

  /// <summary>World-space normal, shown as RGB = (n + 1) / 2.</summary>
  NormalAbsolute,

  /// <summary>Primary rays (samples) per pixel.</summary>
  PrimaryRays,

  /// <summary>All rays per pixel: primary, shadow and secondary.</summary>
  AllRays,

  /// <summary>
  /// The render's estimated standard error of each pixel's value (<see cref="Rendering.Execution.NoiseImage"/>): where
  /// the image is still noisy. None below 2×2 samples per pixel.
  /// </summary>
  Noise,
}
