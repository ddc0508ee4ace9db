namespace GrCis.Hosting;

/// <summary>Which stage of the coarse-to-fine refinement a preview shows.</summary>
public enum PreviewPass
{
  /// <summary>Every n-th pixel rendered, filling its n×n block.</summary>
  Coarse,

  /// <summary>Finished tiles exact, the rest still coarse.</summary>
  Tiles,

  /// <summary>Every pixel with part of its samples (a progressive render's pass).</summary>
  Samples,

  /// <summary>The complete (or stopped) image.</summary>
  Final,
}
