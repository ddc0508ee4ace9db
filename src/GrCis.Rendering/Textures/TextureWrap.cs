namespace Rendering;

/// <summary>What an <see cref="ImageTexture"/> shows outside [0, 1] along one texture axis.</summary>
public enum TextureWrap
{
  /// <summary>The image tiles the axis (OpenGL's REPEAT): coordinate 1.25 shows the same texel as 0.25.</summary>
  Repeat,

  /// <summary>Every other tile is mirrored (MIRRORED_REPEAT), so tiles meet without a seam: 1.25 shows the texel of 0.75.</summary>
  MirroredRepeat,

  /// <summary>The edge texels continue for ever (CLAMP_TO_EDGE): below 0 the first texel, above 1 the last.</summary>
  Clamp,
}
