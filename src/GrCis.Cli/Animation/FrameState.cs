namespace GrCis.Cli.Animation;

/// <summary>What <c>--resume</c> found at a frame's file (<see cref="FrameStore.Check"/>).</summary>
public enum FrameState
{
  /// <summary>No file: the frame is rendered.</summary>
  Missing,

  /// <summary>A whole frame of this very render, its pixels matching their checksum: kept.</summary>
  Kept,

  /// <summary>Cut off, a damaged chunk or image data, or pixels that fail their checksum: rendered again.</summary>
  Corrupt,

  /// <summary>An intact PNG without a frame fingerprint (an older grcis, another program): rendered again.</summary>
  NoFingerprint,

  /// <summary>A frame of another render (another scene, script, size, spp, seed, timing…): rendered again.</summary>
  OtherRender,
}
